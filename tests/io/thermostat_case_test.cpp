// [thermostat] and [[species_thermostat]]: what they accept and refuse, the echo, and the
// ThermostatSpec of the RunSpec.
#include "case_errors.hpp"
#include "io_test_support.hpp"

#include "roughgas/io/case_file.hpp"
#include "roughgas/io/case_schema.hpp"
#include "roughgas/io/run_spec_from_case.hpp"

#include <gtest/gtest.h>

namespace roughgas {
namespace {

using test::replaced;

// Two species heated by white noise of strength 1.
std::string driven_case() {
    return R"([run]
particles = 1000
end = 10.0
density = 0.01

[[species]]
name = "a"
mass = 1.0
radius = 0.5
fraction = 0.5

[[species]]
name = "b"
mass = 2.0
radius = 0.5
fraction = 0.5

[collision]
model = "constant"
alpha = 0.9
beta = 0.5

[thermostat]
strength = 1.0
)";
}

// The same gas in a Langevin bath whose temperature drops from 1 to 0.2 at t = 50.
std::string bath_case() {
    return replaced(
        driven_case(), "strength = 1.0",
        "kind = \"langevin\"\nfriction = 2.0\nrotational_friction = 0.5\nschedule = [[0, 1.0], [50, 0.2]]");
}

using test::error_of;
using test::refused;

TEST(ThermostatCase, WhiteNoiseIsADrivenGasWithOneDrivePerSpecies) {
    const CaseConfig c = parse_case(driven_case(), "case.toml");
    ASSERT_TRUE(c.thermostat.has_value());
    EXPECT_EQ(c.thermostat->kind, ThermostatKind::white_noise);
    EXPECT_EQ(c.thermostat->values.rotational_share, 0.0); // the schema's default, resolved
    EXPECT_FALSE(c.thermostat->exact_energy);
    // The schema's defaults are the config's (code may build a ThermostatConfig by hand).
    EXPECT_EQ(std::get<std::string>(find_key("thermostat.kind")->default_value), name(ThermostatConfig{}.kind));
    EXPECT_EQ(std::get<bool>(find_key("thermostat.exact_energy")->default_value), ThermostatConfig{}.exact_energy);
    EXPECT_TRUE(driven(c));
    EXPECT_FALSE(
        driven(parse_case(replaced(driven_case(), "[thermostat]\nstrength = 1.0\n", ""), "case.toml")));

    const RunSpec s = run_spec_from_case(c);
    ASSERT_TRUE(s.thermostat.has_value());
    EXPECT_EQ(s.thermostat->kind, ThermostatKind::white_noise);
    ASSERT_EQ(s.thermostat->species.size(), 2u);
    for (const SpeciesThermostat& t : s.thermostat->species) {
        EXPECT_EQ(t.drive.t, std::vector<double>{0.0});
        EXPECT_EQ(t.drive.value, std::vector<double>{1.0});
        EXPECT_EQ(t.rotational_share, 0.0);
    }
}

// The species' tables in another order than [[species]]: RunSpec follows [[species]]; what a
// table does not give comes from [thermostat].
TEST(ThermostatCase, SpeciesTablesOverrideThermostatForTheirSpecies) {
    const std::string text = replaced(driven_case(), "strength = 1.0", R"(strength = 1.0
rotational_share = 0.1
exact_energy = true

[[species_thermostat]]
species = "b"
strength = 3.0
rotational_share = 0.25
)");
    const RunSpec s = run_spec_from_case(parse_case(text, "case.toml"));
    ASSERT_TRUE(s.thermostat.has_value());
    EXPECT_TRUE(s.thermostat->exact_energy);
    ASSERT_EQ(s.thermostat->species.size(), 2u);
    EXPECT_EQ(s.thermostat->species[0].drive.value, std::vector<double>{1.0});
    EXPECT_EQ(s.thermostat->species[0].rotational_share, 0.1);
    EXPECT_EQ(s.thermostat->species[1].drive.value, std::vector<double>{3.0});
    EXPECT_EQ(s.thermostat->species[1].rotational_share, 0.25);

    // Every species with a strength of its own: [thermostat] needs none.
    const std::string own =
        replaced(replaced(text, "strength = 1.0\n", ""), "[[species_thermostat]]",
                 "[[species_thermostat]]\nspecies = \"a\"\nstrength = 0.5\n\n[[species_thermostat]]");
    const RunSpec o = run_spec_from_case(parse_case(own, "case.toml"));
    EXPECT_EQ(o.thermostat->species[0].drive.value, std::vector<double>{0.5});
    EXPECT_EQ(o.thermostat->species[1].drive.value, std::vector<double>{3.0});
}

TEST(ThermostatCase, LangevinBathWithSchedule) {
    const std::string text = bath_case() + "\n[[species_thermostat]]\nspecies = \"a\"\nfriction = 4.0\n";
    const CaseConfig c = parse_case(text, "case.toml");
    EXPECT_EQ(c.thermostat->kind, ThermostatKind::langevin);
    EXPECT_FALSE(c.thermostat->values.rotational_share.has_value()); // white noise's, not resolved for a bath
    const RunSpec s = run_spec_from_case(c);
    ASSERT_TRUE(s.thermostat.has_value());
    ASSERT_EQ(s.thermostat->species.size(), 2u);
    for (const SpeciesThermostat& t : s.thermostat->species) {
        EXPECT_EQ(t.drive.t, (std::vector<double>{0.0, 50.0}));
        EXPECT_EQ(t.drive.value, (std::vector<double>{1.0, 0.2}));
        EXPECT_EQ(t.rotational_friction, 0.5);
    }
    EXPECT_EQ(s.thermostat->species[0].friction, 4.0);
    EXPECT_EQ(s.thermostat->species[1].friction, 2.0);
    EXPECT_EQ(parse_case(driven_case(), "c.toml", {"thermostat.rotational_share=0.3"})
                  .thermostat->values.rotational_share,
              0.3);
}

TEST(ThermostatCase, ValuesOutOfRangeAreRefusedWithFileLineKeyAndRange) {
    // strength is on line 24 of driven_case().
    EXPECT_EQ(error_of(replaced(driven_case(), "strength = 1.0", "strength = -1.0")),
              "case.toml:24:12: thermostat.strength = -1: must be >= 0 (length^2/time^3)");
    EXPECT_TRUE(refused(driven_case(), {"thermostat.rotational_share=1.5"},
                        "thermostat.rotational_share = 1.5: must be in [0, 1]"));
    EXPECT_TRUE(refused(driven_case(), {"thermostat.rotational_share=-0.1"},
                        "thermostat.rotational_share = -0.1: must be in [0, 1]"));
    EXPECT_TRUE(
        refused(bath_case(), {"thermostat.friction=0"}, "thermostat.friction = 0: must be > 0 (1/time)"));
    EXPECT_TRUE(refused(bath_case(), {"thermostat.rotational_friction=-1"},
                        "thermostat.rotational_friction = -1: must be >= 0 (1/time)"));
    EXPECT_TRUE(refused(driven_case(), {"thermostat.kind=heater"},
                        "thermostat.kind = \"heater\": must be one of "
                        "\"white_noise\", \"langevin\""));
    EXPECT_EQ(error_of(driven_case(), {"thermostat.strength=0"}), ""); // a drive of 0 is a drive
}

TEST(ThermostatCase, ScheduleStartsAtZeroAndIncreases) {
    const std::string no_strength = replaced(driven_case(), "strength = 1.0\n", "");
    const auto with = [&](const std::string& schedule) {
        return no_strength + "schedule = " + schedule + "\n";
    };
    EXPECT_EQ(error_of(with("[[0, 1.0], [5, 0.0], [7.5, 2]]")), "");
    EXPECT_TRUE(refused(with("[[1, 1.0]]"), {}, "thermostat.schedule[0] = [1, 1]: the first time must be 0"));
    EXPECT_TRUE(refused(
        with("[[0, 1.0], [5, 2.0], [5, 3.0]]"), {},
        "thermostat.schedule[2] = [5, 3]: its time must be > 5, the time before it (the times increase "
        "strictly)"));
    EXPECT_TRUE(refused(with("[[0, 1.0], [5, 2.0], [4, 3.0]]"), {},
                        "thermostat.schedule[2] = [4, 3]: its time must be > 5"));
    EXPECT_TRUE(
        refused(with("[[0, 1.0], [5, -2.0]]"), {},
                "thermostat.schedule[1][1] = -2: must be >= 0 ([time, strength or bath_temperature])"));
    EXPECT_TRUE(refused(with("[0, 1.0]"), {},
                        "thermostat.schedule = [ 0, 1.0 ]: must be an array of [real, real] pairs"));
    EXPECT_TRUE(refused(with("[]"), {}, "must be an array of [real, real] pairs, at least one"));
    EXPECT_TRUE(refused(with("[[0, 1.0, 2.0]]"), {}, "must be an array of [real, real] pairs"));
    EXPECT_TRUE(refused(with("[[0, \"hot\"]]"), {},
                        "thermostat.schedule[0][1] = \"hot\": must be a real number >= 0"));
    // A bath's temperatures are > 0.
    EXPECT_TRUE(refused(bath_case(), {"thermostat.schedule=[[0, 1.0], [50, 0]]"},
                        "thermostat.schedule[1] = [50, 0]: a bath temperature must be > 0 (energy)"));
    // With --set, as in the file.
    const CaseConfig c = parse_case(no_strength, "case.toml", {"thermostat.schedule=[[0, 2.0], [10, 1.0]]"});
    EXPECT_EQ(c.thermostat->schedule, (std::vector<std::array<double, 2>>{{0.0, 2.0}, {10.0, 1.0}}));
    EXPECT_TRUE(refused(no_strength, {"thermostat.schedule=[[0, 2.0], [-1, 1.0]]"},
                        "thermostat.schedule[1][0] = -1: must be >= 0 ([time, strength or bath_temperature]) "
                        "(set with --set)"));
}

TEST(ThermostatCase, TheDriveIsGivenOnceForEverySpecies) {
    const std::string no_strength = replaced(driven_case(), "strength = 1.0\n", "");
    EXPECT_TRUE(refused(
        no_strength, {},
        "thermostat.strength: required for thermostat.kind = \"white_noise\" but missing (must be a real "
        "number >= 0 (length^2/time^3); or give thermostat.schedule)"));
    // One species with its own strength: the other still needs [thermostat]'s, and is named.
    EXPECT_TRUE(refused(no_strength + "\n[[species_thermostat]]\nspecies = \"b\"\nstrength = 2.0\n", {},
                        "or give thermostat.schedule; species \"a\" without their own)"));
    EXPECT_TRUE(refused(
        driven_case(), {"thermostat.schedule=[[0, 1.0]]"},
        "thermostat.strength = 1 with thermostat.schedule: give the drive either constant (strength) or over "
        "time (schedule), not both"));
    EXPECT_TRUE(refused(
        no_strength + "schedule = [[0, 1.0]]\n\n[[species_thermostat]]\nspecies = \"b\"\nstrength = 2.0\n",
        {},
        "species_thermostat.0.strength = 2 with thermostat.schedule: the schedule drives every species over "
        "time and a species has no schedule of its own"));
    const std::string bath = replaced(bath_case(), "schedule = [[0, 1.0], [50, 0.2]]", "");
    EXPECT_TRUE(
        refused(bath, {},
                "thermostat.bath_temperature: required for thermostat.kind = \"langevin\" but missing "
                "(must be a real number > 0 (energy); or give thermostat.schedule)"));
    EXPECT_TRUE(refused(bath_case(), {"thermostat.bath_temperature=1.0"},
                        "thermostat.bath_temperature = 1 with thermostat.schedule: give the drive either"));
    const std::string frictionless = replaced(bath_case(), "friction = 2.0\n", "");
    EXPECT_TRUE(refused(
        frictionless, {},
        "thermostat.friction: required for thermostat.kind = \"langevin\" but missing (must be a real "
        "number > 0 (1/time): a bath without friction neither heats nor cools the gas)"));
    EXPECT_EQ(error_of(frictionless + "\n[[species_thermostat]]\nspecies = \"a\"\nfriction = 1.0\n"
                                      "\n[[species_thermostat]]\nspecies = \"b\"\nfriction = 3.0\n"),
              "");
}

// A key of the other kind means the kind is set wrong: refused, in [thermostat] and in a species' table.
TEST(ThermostatCase, KeysOfTheOtherKindAreRefused) {
    EXPECT_TRUE(refused(
        driven_case(), {"thermostat.friction=1"},
        "thermostat.friction = 1: a key of the Langevin bath, but thermostat.kind = \"white_noise\" "
        "(white noise reads strength, rotational_share, exact_energy and schedule; kind = \"langevin\" "
        "for a bath)"));
    EXPECT_TRUE(refused(driven_case(), {"thermostat.bath_temperature=1.0"},
                        "thermostat.bath_temperature = 1: a key of "
                        "the Langevin bath"));
    EXPECT_TRUE(
        refused(bath_case(), {"thermostat.exact_energy=true"},
                "thermostat.exact_energy = true: a key of white noise, but thermostat.kind = \"langevin\" (a "
                "Langevin bath reads bath_temperature, friction, rotational_friction and schedule)"));
    EXPECT_TRUE(
        refused(bath_case(), {"thermostat.strength=1.0"}, "thermostat.strength = 1: a key of white noise"));
    EXPECT_TRUE(refused(bath_case(),
                        {"species_thermostat.0.species=a", "species_thermostat.0.rotational_share=0.5"},
                        "species_thermostat.0.rotational_share = 0.5: a key of white noise"));
    EXPECT_TRUE(refused(driven_case(),
                        {"species_thermostat.0.species=b", "species_thermostat.0.rotational_friction=1"},
                        "species_thermostat.0.rotational_friction = 1: a key of the Langevin bath"));
    // exact_energy and kind belong to [thermostat] alone.
    EXPECT_TRUE(refused(
        driven_case(), {"species_thermostat.0.species=b", "species_thermostat.0.exact_energy=true"},
        "species_thermostat.0.exact_energy: unknown key (did you mean exact_energy in [thermostat]?)"));
}

TEST(ThermostatCase, SpeciesTablesNameOneSpeciesEach) {
    EXPECT_TRUE(refused(driven_case(), {"species_thermostat.0.species=c"},
                        "species_thermostat.0.species = \"c\": not a species (must be one of \"a\", \"b\")"));
    EXPECT_TRUE(
        refused(driven_case(), {"species_thermostat.0.species=b", "species_thermostat.1.species=b"},
                "species_thermostat.1.species = \"b\": species_thermostat.0 already sets this species (one "
                "[[species_thermostat]] per species)"));
    EXPECT_TRUE(refused(driven_case(), {"species_thermostat.0.strength=2"},
                        "species_thermostat.0.species: required key is missing (must be a string)"));
    EXPECT_TRUE(refused(replaced(driven_case(), "[thermostat]\nstrength = 1.0\n", ""),
                        {"species_thermostat.0.species=b"},
                        "[[species_thermostat]] without [thermostat]: give [thermostat]"));
}

// A box takes a thermostat (a uniformly heated gas), walls and gravity too; uniform shear flow,
// homogeneous or a sheared box, does not.
TEST(ThermostatCase, OnlyUnshearedGasesTakeAThermostat) {
    EXPECT_TRUE(
        refused(driven_case(), {"run.kind=shear", "shear.rate=1"},
                "[thermostat] with run.kind = \"shear\": a thermostat drives a gas that is not sheared"));
    EXPECT_EQ(error_of(driven_case(),
                       {"domain.size=[10.0, 10.0, 10.0]", "domain.cells=[2, 2, 2]", "domain.allow_coarse=true"}),
              "");
}

// A heated gas does not cool without end, so its run may be as long as it likes; white noise of
// strength 0 throughout leaves it cooling freely, and the reach of a cooling gas is checked.
TEST(ThermostatCase, CoolingReachIsCheckedOnlyWhenNothingHeats) {
    EXPECT_EQ(error_of(driven_case(), {"run.end=1e6"}), "");
    EXPECT_EQ(error_of(bath_case(), {"run.end=1e6"}), "");
    const std::string reach = "reaches T_tr/m = 1e-300 (velocities squared underflow)";
    EXPECT_TRUE(
        refused(replaced(driven_case(), "[thermostat]\nstrength = 1.0\n", ""), {"run.end=1e6"}, reach));
    EXPECT_TRUE(refused(driven_case(), {"thermostat.strength=0", "run.end=1e6"}, reach));
    EXPECT_EQ(error_of(replaced(driven_case(), "strength = 1.0", "schedule = [[0, 0.0], [5, 1.0]]"),
                       {"run.end=1e6"}),
              "");
}

TEST(ThermostatCase, EmitParseRoundTrip) {
    const std::vector<std::string> texts = {
        driven_case(),
        replaced(
            driven_case(), "strength = 1.0",
            "schedule = [[0, 1.0], [2.5, 0.0], [40, 1e-3]]\nrotational_share = 0.5\nexact_energy = true\n\n"
            "[[species_thermostat]]\nspecies = \"b\"\nrotational_share = 1.0"),
        bath_case() +
            "\n[[species_thermostat]]\nspecies = \"b\"\nfriction = 0.1\nrotational_friction = 3.0\n",
        replaced(bath_case(), "schedule = [[0, 1.0], [50, 0.2]]", "bath_temperature = 10.0")};
    for (const std::string& t : texts) {
        const CaseConfig c = parse_case(t, "c.toml");
        const std::string emitted = emit_case(c);
        EXPECT_EQ(parse_case(emitted, "emitted.toml"), c) << emitted;
        EXPECT_NE(emitted.find("[thermostat]"), std::string::npos) << emitted;
    }
}

// The command line: a refused thermostat exits 2 naming the file and the key, and writes nothing;
// a driven gas's summary is its steady state.
TEST(ThermostatCase, CommandsRefuseAndSummarizeADrivenGas) {
    const test::ScratchDir dir;
    const test::fs::path bad = dir.write("bad.toml", replaced(bath_case(), "friction = 2.0\n", ""));
    const test::CommandResult r = test::run_roughgas("check '" + bad.string() + "'", dir);
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("bad.toml"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("thermostat.friction: required for thermostat.kind = \"langevin\""),
              std::string::npos)
        << r.err;
    const test::fs::path good = dir.write("good.toml", driven_case());
    const test::CommandResult run = test::run_roughgas(
        "run '" + good.string() + "' --quiet --set run.end=2 --out '" + (dir / "out").string() + "'", dir);
    ASSERT_EQ(run.status, 0) << run.err;
    EXPECT_TRUE(test::fs::exists(dir / "out" / "steady.csv"));
    EXPECT_FALSE(test::fs::exists(dir / "out" / "scaled.csv"));
}

} // namespace
} // namespace roughgas
