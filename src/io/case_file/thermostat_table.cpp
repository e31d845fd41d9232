// [thermostat] and [[species_thermostat]]: their build, their checks and their emission.
#include "thermostat_table.hpp"

#include "messages.hpp"
#include "toml_access.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <string>
#include <string_view>

namespace roughgas::case_file {
namespace {

constexpr bool white(ThermostatKind k) {
    return k == ThermostatKind::white_noise;
}

// The key of the drive (DriveSchedule) of a kind when it is constant.
std::string_view drive_key(ThermostatKind k) {
    return white(k) ? "strength" : "bath_temperature";
}

// The keys of its own each kind reads; those of the other kind are refused, not kept as unused
// (CaseConfig::unused): a bath's friction under white noise, or a strength given a bath, means the
// kind is set wrong, and the run would silently drive the gas otherwise than the case reads.
using KeyList = std::array<std::string_view, 3>;
constexpr KeyList white_noise_keys{"strength", "rotational_share", "exact_energy"};
constexpr KeyList langevin_keys{"bath_temperature", "friction", "rotational_friction"};
bool kind_reads(ThermostatKind k, std::string_view key) {
    const KeyList& own = white(k) ? white_noise_keys : langevin_keys;
    return key == "kind" || key == "schedule" || key == "species" ||
           std::find(own.begin(), own.end(), key) != own.end();
}
std::string listed(const KeyList& keys) {
    return join(std::vector<std::string>(keys.begin(), keys.end()));
}

void check_kind_keys(BuildContext& ctx, const toml::table* t, const std::string& prefix,
                     ThermostatKind kind) {
    if (t == nullptr)
        return;
    for (auto&& [k, node] : *t) {
        if (kind_reads(kind, k.str()))
            continue;
        const std::string key = prefix + "." + std::string(k.str());
        ctx.add(key, white(kind)
                         ? fmt::format("{} = {}: a key of the Langevin bath, but thermostat.kind = "
                                       "\"white_noise\" (white noise reads {} and schedule; "
                                       "kind = \"langevin\" for a bath)",
                                       key, value_text(node), listed(white_noise_keys))
                         : fmt::format("{} = {}: a key of white noise, but thermostat.kind = \"langevin\" "
                                       "(a Langevin bath reads {} and schedule)",
                                       key, value_text(node), listed(langevin_keys)));
    }
}

// The schedule's times start at 0 and increase; a bath's temperatures are > 0 (the schema pass
// checked that every number is >= 0).
void check_schedule(BuildContext& ctx, const ThermostatConfig& t) {
    const std::vector<std::array<double, 2>>& s = t.schedule;
    if (s.empty())
        return;
    if (s[0][0] != 0)
        ctx.add("thermostat.schedule",
                fmt::format(
                    "thermostat.schedule[0] = [{}, {}]: the first time must be 0 (the drive from the start "
                    "of the run)",
                    s[0][0], s[0][1]),
                "thermostat.schedule.0");
    for (std::size_t k = 0; k < s.size(); ++k) {
        const std::string at = fmt::format("thermostat.schedule.{}", k);
        if (k > 0 && !(s[k][0] > s[k - 1][0]))
            ctx.add(
                "thermostat.schedule",
                fmt::format("thermostat.schedule[{}] = [{}, {}]: its time must be > {}, the time before it "
                            "(the times increase strictly)",
                            k, s[k][0], s[k][1], s[k - 1][0]),
                at);
        if (!white(t.kind) && !(s[k][1] > 0))
            ctx.add("thermostat.schedule",
                    fmt::format("thermostat.schedule[{}] = [{}, {}]: a bath temperature must be > 0 (energy)",
                                k, s[k][0], s[k][1]),
                    at);
    }
}

// The names of the species the case has, quoted: "a", "b".
std::string species_names(const CaseConfig& c) {
    std::vector<std::string> names;
    for (const SpeciesConfig& s : c.species)
        names.push_back(quote(s.name));
    return join(names);
}

void check_species_tables(BuildContext& ctx, const CaseConfig& c) {
    const std::vector<SpeciesThermostatConfig>& st = c.species_thermostats;
    for (std::size_t i = 0; i < st.size(); ++i) {
        const std::string key = fmt::format("species_thermostat.{}.species", i);
        if (std::none_of(c.species.begin(), c.species.end(),
                         [&](const SpeciesConfig& s) { return s.name == st[i].species; }))
            ctx.add(key, fmt::format("{} = {}: not a species (must be one of {})", key, quote(st[i].species),
                                     species_names(c)));
        for (std::size_t j = 0; j < i; ++j)
            if (st[j].species == st[i].species)
                ctx.add(key, fmt::format("{} = {}: species_thermostat.{} already sets this species (one "
                                         "[[species_thermostat]] per species)",
                                         key, quote(st[i].species), j));
    }
}

// The drive: a schedule, or a constant value for every species ([thermostat]'s or the species' own);
// never both, since the schedule is the one drive of every species over time. A bath needs its
// friction either way.
void check_drive(BuildContext& ctx, const CaseConfig& c) {
    const ThermostatConfig& t = *c.thermostat;
    const std::string_view drive = drive_key(t.kind);
    const auto given = [&](const ThermostatValues& v) { return white(t.kind) ? v.strength : v.bath_temperature; };
    if (!t.schedule.empty()) {
        if (const std::optional<double> x = given(t.values))
            ctx.add(fmt::format("thermostat.{}", drive),
                    fmt::format("thermostat.{} = {} with thermostat.schedule: give the drive either constant ({}) "
                                "or over time (schedule), not both",
                                drive, *x, drive));
        for (std::size_t i = 0; i < c.species_thermostats.size(); ++i)
            if (const std::optional<double> x = given(c.species_thermostats[i].values))
                ctx.add(fmt::format("species_thermostat.{}.{}", i, drive),
                        fmt::format("species_thermostat.{}.{} = {} with thermostat.schedule: the schedule drives "
                                    "every species over time and a species has no schedule of its own (drop the "
                                    "schedule, or this species' {})",
                                    i, drive, *x, drive));
    }
    // `key` of [thermostat], unless every species has its own; `how`: what the message adds.
    const auto require = [&](std::optional<double> ThermostatValues::*field, std::string_view key,
                             std::string_view how) {
        std::vector<std::string> without;
        for (std::size_t i = 0; i < c.species.size(); ++i)
            if (!(thermostat_for(c, i).*field))
                without.push_back(quote(c.species[i].name));
        if (without.empty())
            return;
        const std::string path = fmt::format("thermostat.{}", key);
        // When some species have their own, those that have not.
        const std::string which = without.size() < c.species.size()
                                      ? fmt::format("; species {} without their own", join(without))
                                      : std::string();
        ctx.add(path,
                fmt::format("{}: required for thermostat.kind = \"{}\" but missing (must be {}{}{})", path,
                            name(t.kind), expectation(*find_key(path)), how, which),
                "thermostat");
    };
    if (t.schedule.empty())
        require(white(t.kind) ? &ThermostatValues::strength : &ThermostatValues::bath_temperature, drive,
                "; or give thermostat.schedule");
    if (!white(t.kind))
        require(&ThermostatValues::friction, "friction", ": a bath without friction neither heats nor cools the gas");
}

ThermostatValues read_values(const Reader& r) {
    ThermostatValues v;
    v.strength = r.opt_real("strength");
    v.bath_temperature = r.opt_real("bath_temperature");
    v.rotational_share = r.opt_real("rotational_share");
    v.friction = r.opt_real("friction");
    v.rotational_friction = r.opt_real("rotational_friction");
    return v;
}

void emit_values(Emitter& e, const ThermostatValues& v) {
    e.put("strength", v.strength);
    e.put("bath_temperature", v.bath_temperature);
    e.put("rotational_share", v.rotational_share);
    e.put("friction", v.friction);
    e.put("rotational_friction", v.rotational_friction);
}

} // namespace

std::optional<ThermostatConfig> build_thermostat(const toml::table& root) {
    const toml::table* t = root["thermostat"].as_table();
    if (t == nullptr)
        return std::nullopt;
    const Reader r(t, "thermostat");
    ThermostatConfig c;
    c.kind = r.choice<ThermostatKind>("kind", thermostat_kind_names);
    c.values = read_values(r);
    // The kind's defaulted values, resolved; the other kind's stay as given (and are refused).
    if (white(c.kind))
        c.values.rotational_share = r.real("rotational_share");
    else
        c.values.rotational_friction = r.real("rotational_friction");
    c.exact_energy = r.boolean("exact_energy");
    c.schedule = r.real_pairs("schedule");
    return c;
}

std::vector<SpeciesThermostatConfig> build_species_thermostats(const toml::table& root) {
    std::vector<SpeciesThermostatConfig> list;
    if (const toml::array* a = root["species_thermostat"].as_array())
        for (const toml::node& n : *a) {
            const Reader r(n.as_table(), "species_thermostat");
            list.push_back({r.string("species"), read_values(r)});
        }
    return list;
}

void check_thermostat(BuildContext& ctx, const CaseConfig& c) {
    if (!c.thermostat) {
        if (!c.species_thermostats.empty())
            ctx.add("species_thermostat",
                    "[[species_thermostat]] without [thermostat]: give [thermostat] (its "
                    "kind, and the values of the species without a table of their own)");
        return;
    }
    const ThermostatConfig& t = *c.thermostat;
    if (c.run.kind == RunKind::shear)
        ctx.add("thermostat", "[thermostat] with run.kind = \"shear\": a thermostat drives a gas that is not "
                              "sheared (run.kind = \"cooling\"); uniform shear flow heats the gas itself");
    const toml::table& root = ctx.root();
    check_kind_keys(ctx, root["thermostat"].as_table(), "thermostat", t.kind);
    if (const toml::array* a = root["species_thermostat"].as_array())
        for (std::size_t i = 0; i < a->size(); ++i)
            check_kind_keys(ctx, a->get(i)->as_table(), fmt::format("species_thermostat.{}", i), t.kind);
    check_schedule(ctx, t);
    check_species_tables(ctx, c);
    check_drive(ctx, c);
}

bool thermostat_heats(const CaseConfig& c) {
    const ThermostatConfig& t = c.thermostat.value();
    if (!white(t.kind))
        return true;
    if (std::any_of(t.schedule.begin(), t.schedule.end(),
                    [](const std::array<double, 2>& p) { return p[1] > 0; }))
        return true;
    for (std::size_t i = 0; i < c.species.size(); ++i)
        if (thermostat_for(c, i).strength.value_or(0.0) > 0)
            return true;
    return false;
}

void emit_thermostat(Emitter& e, const ThermostatConfig& t) {
    e.header("[thermostat]");
    e.put("kind", name(t.kind));
    emit_values(e, t.values);
    if (white(t.kind))
        e.put("exact_energy", t.exact_energy);
    if (!t.schedule.empty())
        e.put("schedule", t.schedule);
}

void emit_species_thermostats(Emitter& e, const std::vector<SpeciesThermostatConfig>& list) {
    for (const SpeciesThermostatConfig& s : list) {
        e.header("[[species_thermostat]]");
        e.put("species", s.species);
        emit_values(e, s.values);
    }
}

} // namespace roughgas::case_file
