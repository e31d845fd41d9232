// Case-file parsing in-process: defaults, --set, messages, cross-key rules, emit/parse round trip.
#include "io_test_support.hpp"

#include "roughgas/io/case_file.hpp"
#include "roughgas/io/case_schema.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace roughgas {
namespace {

using test::replaced;
using test::small_case;

// The first message of the InputError that parsing `text` throws ("" if it does not throw).
std::string error_of(const std::string& text, const std::vector<std::string>& sets = {},
                     CaseUse use = CaseUse::run) {
    try {
        (void)parse_case(text, "case.toml", sets, use);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

TEST(CaseFile, AppliesSchemaDefaults) {
    const CaseConfig c = parse_case(small_case(), "case.toml");
    EXPECT_EQ(c.run.kind, RunKind::cooling);
    EXPECT_EQ(c.run.density, 1.0);
    EXPECT_EQ(c.run.replicas, 1);
    EXPECT_EQ(c.run.seed, 1u);
    EXPECT_EQ(c.run.output_spacing, OutputSpacing::linear);
    ASSERT_EQ(c.species.size(), 1u);
    EXPECT_EQ(c.species[0].inertia, 0.4);
    EXPECT_EQ(c.species[0].fraction, 1.0);
    EXPECT_EQ(c.contact.model, (ContactModel{NormalForm::eq24, ContactEnd::force}));
    EXPECT_TRUE(c.contact.cache);
    EXPECT_EQ(c.contact.cache_file, "");
    EXPECT_EQ(c.contact.tolerance.rel, 1e-12);
    EXPECT_FALSE(c.collision.direct);
    EXPECT_FALSE(c.shear.has_value());
    ASSERT_TRUE(c.material.has_value());
    EXPECT_EQ(c.material->material().young_modulus, 1.0e10);
    EXPECT_EQ(c.material->material().asperity, 1.0e-6);
}

TEST(CaseFile, SchemaDefaultsMatchTheConfigStructs) {
    // Two places state defaults (schema for docs and parsing, struct initialisers for code that builds
    // a CaseConfig by hand): they must agree.
    const RunConfig run;
    const SpeciesConfig sp;
    const ContactConfig ct;
    const RestitutionGridConfig g;
    EXPECT_EQ(std::get<double>(find_key("run.density")->default_value), run.density);
    EXPECT_EQ(std::get<std::int64_t>(find_key("run.replicas")->default_value), run.replicas);
    EXPECT_EQ(std::get<std::int64_t>(find_key("run.seed")->default_value),
              static_cast<std::int64_t>(run.seed));
    EXPECT_EQ(std::get<double>(find_key("run.output_every")->default_value), run.output_every);
    EXPECT_EQ(std::get<std::string>(find_key("species.name")->default_value), sp.name);
    EXPECT_EQ(std::get<double>(find_key("species.inertia")->default_value), sp.inertia);
    EXPECT_EQ(std::get<double>(find_key("species.fraction")->default_value), sp.fraction);
    EXPECT_EQ(std::get<double>(find_key("species.temperature")->default_value), sp.temperature);
    EXPECT_EQ(std::get<double>(find_key("species.rotational_temperature")->default_value),
              sp.rotational_temperature);
    EXPECT_EQ(std::get<bool>(find_key("contact.cache")->default_value), ct.cache);
    EXPECT_EQ(std::get<double>(find_key("contact.tolerance")->default_value), ct.tolerance.rel);
    EXPECT_EQ(std::get<double>(find_key("restitution.g_n_min")->default_value), g.g_n_min);
    EXPECT_EQ(std::get<double>(find_key("restitution.g_n_max")->default_value), g.g_n_max);
    EXPECT_EQ(std::get<std::int64_t>(find_key("restitution.g_n_points")->default_value), g.g_n_points);
    EXPECT_EQ(std::get<double>(find_key("restitution.g_t_min")->default_value), g.g_t_min);
    EXPECT_EQ(std::get<double>(find_key("restitution.g_t_max")->default_value), g.g_t_max);
    EXPECT_EQ(std::get<std::int64_t>(find_key("restitution.g_t_points")->default_value), g.g_t_points);
}

TEST(CaseFile, SetOverridesBeforeValidation) {
    const CaseConfig c =
        parse_case(small_case(), "case.toml",
                   {"species.0.radius=0.5", "run.particles=20000", "collision.model=\"constant\"",
                    "collision.alpha=0.7", "collision.beta = 0", "contact.form=eq25"});
    EXPECT_EQ(c.species[0].radius, 0.5);
    EXPECT_EQ(c.run.particles, 20000);
    EXPECT_EQ(c.collision.model, CollisionModel::constant);
    EXPECT_EQ(c.collision.alpha, 0.7);
    EXPECT_EQ(c.collision.beta, 0.0);
    EXPECT_EQ(c.contact.model.form, NormalForm::eq25);
}

TEST(CaseFile, SetAcceptsQuotedAndBareStrings) {
    const std::string text = replaced(small_case(), "model = \"brilliantov\"", "model = \"viscoelastic\"");
    EXPECT_EQ(parse_case(text, "c.toml", {"collision.model=brilliantov"}).collision.model,
              CollisionModel::brilliantov);
    EXPECT_EQ(parse_case(text, "c.toml", {"collision.model=\"brilliantov\""}).collision.model,
              CollisionModel::brilliantov);
    EXPECT_EQ(parse_case(text, "c.toml", {"species.0.name=true"}).species[0].name, "true"); // string key
}

TEST(CaseFile, SetCreatesTablesAndOneMoreArrayElement) {
    const CaseConfig c =
        parse_case(small_case(), "c.toml",
                   {"species.0.fraction=0.5", "species.1.name=b", "species.1.mass=1e-3",
                    "species.1.radius=0.005", "species.1.fraction=0.5", "shear.rate=2", "run.kind=shear"});
    ASSERT_EQ(c.species.size(), 2u);
    EXPECT_EQ(c.species[1].name, "b");
    EXPECT_EQ(c.species[1].radius, 0.005);
    ASSERT_TRUE(c.shear.has_value());
    EXPECT_EQ(c.shear->rate, 2.0);
}

TEST(CaseFile, SetErrorsNameTheArgument) {
    EXPECT_NE(error_of(small_case(), {"collision.alpha"}).find("expected KEY=VALUE"), std::string::npos);
    EXPECT_NE(error_of(small_case(), {"species.radius=1"}).find("species.N.radius"), std::string::npos);
    EXPECT_NE(error_of(small_case(), {"species.5.radius=1"}).find("index must be <= 1"), std::string::npos);
    EXPECT_NE(error_of(small_case(), {"alpha=1"}).find("dotted path"), std::string::npos);
    const std::string e = error_of(small_case(), {"species.0.radius=-1"});
    EXPECT_NE(e.find("case.toml: species.0.radius = -1: must be > 0 (length) (set with --set)"),
              std::string::npos)
        << e;
    // An element of an array given with --set: no line and column of the case file.
    const std::string a = error_of(small_case(), {"domain.size=[10.0, 10.0, 10.0]", "domain.cells=[0, 2, 2]",
                                                  "domain.allow_coarse=true"});
    EXPECT_NE(a.find("case.toml: domain.cells[0] = 0: must be in [1, 4096] (set with --set)"), std::string::npos)
        << a;
}

TEST(CaseFile, MessageHasFileLineColumnKeyValueAndRange) {
    const std::string text = replaced(small_case(), "young_modulus = 1.0e10", "young_modulus = -1e10");
    // young_modulus is on line 14 of small_case().
    EXPECT_EQ(error_of(text), "case.toml:14:17: material.young_modulus = -10000000000: must be > 0 (Pa)");
}

// A cadence of more than 10^7 linear rows is refused before the run lists them, on either clock;
// log-spaced rows and a cadence at the limit are not.
TEST(CaseFile, RefusesMoreOutputRowsThanARunWrites) {
    const std::string e = error_of(small_case(), {"run.output_every=1e-9"});
    EXPECT_NE(e.find("run.output_every = 1e-09: 1e+10 rows to run.end = 10, more than a run writes (must be >= "
                     "run.end/1e+07 = 1e-06, or output_spacing = \"log\")"),
              std::string::npos)
        << e;
    EXPECT_EQ(error_of(small_case(), {"run.output_every=1e-6"}), "");
    EXPECT_EQ(error_of(small_case(), {"run.output_every=1e-9", "run.output_spacing=log"}), "");
    EXPECT_NE(error_of(small_case(), {"run.histogram_every=1e-9"}).find("run.histogram_every = 1e-09: "),
              std::string::npos);
    const std::string t = error_of(small_case(), {"run.end_time=5.0", "run.output_every_time=1e-7"});
    EXPECT_NE(t.find("run.output_every_time = 1e-07: 5e+07 rows to run.end_time = 5,"), std::string::npos) << t;
}

TEST(CaseFile, ReportsEveryIssueOfAPass) {
    std::string text = replaced(small_case(), "poisson_ratio = 0.3", "poisson_ratio = 0.7");
    text = replaced(text, "friction = 1.0e-3", "friction = -1");
    const std::string e = error_of(text);
    EXPECT_NE(e.find("material.poisson_ratio = 0.7: must be in (-1, 0.5)"), std::string::npos) << e;
    EXPECT_NE(e.find("material.friction = -1: must be >= 0"), std::string::npos) << e;
}

TEST(CaseFile, UnknownKeysGetSuggestions) {
    EXPECT_NE(error_of(replaced(small_case(), "young_modulus", "youngs_modulus"))
                  .find("material.youngs_modulus: unknown key (did you mean material.young_modulus?)"),
              std::string::npos);
    EXPECT_NE(error_of(replaced(small_case(), "[material]", "[materail]")).find("did you mean [material]?"),
              std::string::npos);
    EXPECT_NE(error_of(replaced(small_case(), "end = 10.0", "end = 10.0\nseeed = 3"))
                  .find("run.seeed: unknown key (did you mean run.seed?)"),
              std::string::npos);
    // A right key in the wrong table.
    EXPECT_NE(error_of(replaced(small_case(), "end = 10.0", "end = 10.0\nasperity = 1e-6"))
                  .find("did you mean asperity in [material]?"),
              std::string::npos);
    // Far from everything: the message lists the table's keys instead.
    EXPECT_NE(
        error_of(replaced(small_case(), "end = 10.0", "end = 10.0\nzzzzzzzz = 1")).find("[run] allows kind"),
        std::string::npos);
    EXPECT_NE(error_of(small_case(), {"collision.model=brilliantv"}).find("did you mean \"brilliantov\"?"),
              std::string::npos);
}

TEST(CaseFile, TypesAreChecked) {
    EXPECT_NE(
        error_of(small_case(), {"run.particles=1.5"}).find("run.particles = 1.5: must be an integer >= 2"),
        std::string::npos);
    EXPECT_EQ(parse_case(small_case(), "c.toml", {"run.particles=1e5"}).run.particles,
              100000); // integral float
    EXPECT_NE(error_of(small_case(), {"species.0.radius=\"big\""}).find("must be a real number > 0 (length)"),
              std::string::npos);
    EXPECT_NE(error_of(small_case(), {"contact.cache=1"}).find("must be true or false"), std::string::npos);
    EXPECT_NE(error_of(small_case(), {"material.young_modulus=inf"}).find("must be a real number > 0"),
              std::string::npos);
    EXPECT_NE(error_of(replaced(small_case(), "[[species]]", "[species]")).find("[[species]]"),
              std::string::npos);
    EXPECT_NE(error_of("[run\n").find("case.toml:1:"), std::string::npos); // TOML syntax error with position
}

TEST(CaseFile, ModelDependentRequirements) {
    const std::string constant = replaced(small_case(), "model = \"brilliantov\"", "model = \"constant\"");
    const std::string e = error_of(constant);
    EXPECT_NE(
        e.find("collision.alpha: required for collision.model = \"constant\" but missing (must be a real "
               "number in [0, 1])"),
        std::string::npos)
        << e;
    EXPECT_NE(e.find("collision.beta: required"), std::string::npos) << e;
    EXPECT_EQ(error_of(constant, {"collision.alpha=0.9", "collision.beta=0"}), "");

    const std::string no_asperity = replaced(small_case(), "asperity = 1.0e-6", "");
    EXPECT_NE(error_of(no_asperity).find("material.asperity: required for collision.model = \"brilliantov\""),
              std::string::npos);
    const std::string visco = replaced(no_asperity, "model = \"brilliantov\"", "model = \"viscoelastic\"");
    EXPECT_EQ(error_of(visco), "");
    EXPECT_NE(error_of(visco, {}, CaseUse::restitution)
                  .find("material.asperity: required for roughgas restitution"),
              std::string::npos);

    const std::size_t m = small_case().find("[material]");
    const std::size_t r = small_case().find("[restitution]");
    const std::string no_material = small_case().substr(0, m) + small_case().substr(r);
    EXPECT_NE(error_of(no_material)
                  .find("material: the [material] table is required for collision.model = "
                        "\"brilliantov\""),
              std::string::npos);
    EXPECT_NE(
        error_of(small_case(), {"run.kind=shear"}).find("shear.rate: required for run.kind = \"shear\""),
        std::string::npos);
}

TEST(CaseFile, DissipationFromViscosities) {
    const std::string viscous = replaced(small_case(), "dissipation = 1.0e-5", "eta1 = 1.0e4\neta2 = 2.0e4");
    const CaseConfig c = parse_case(viscous, "c.toml");
    EXPECT_DOUBLE_EQ(c.material->dissipation, dissipation_from_viscosities(1.0e4, 2.0e4, 1.0e10, 0.3));
    EXPECT_NE(error_of(replaced(small_case(), "dissipation = 1.0e-5",
                                "dissipation = 1.0e-5\neta1 = 1.0\neta2 = 1.0"))
                  .find("not both"),
              std::string::npos);
    EXPECT_NE(error_of(replaced(small_case(), "dissipation = 1.0e-5", "eta1 = 1.0"))
                  .find("material.eta2: required"),
              std::string::npos);
    EXPECT_NE(
        error_of(replaced(small_case(), "dissipation = 1.0e-5", "")).find("material.dissipation: required"),
        std::string::npos);
    EXPECT_NE(error_of(viscous, {"material.poisson_ratio=0"}).find("poisson_ratio != 0"), std::string::npos);
}

TEST(CaseFile, MassFromDensity) {
    // A uniform sphere: m = (4/3) pi R^3 density (R = 0.01 m in small_case).
    const std::string by_density = replaced(small_case(), "mass = 4.188790204786391e-3", "density = 1000.0");
    const CaseConfig c = parse_case(by_density, "c.toml");
    EXPECT_NEAR(c.species[0].mass, 4.0 / 3.0 * std::numbers::pi * 1e-6 * 1000.0, 1e-18);
    EXPECT_EQ(parse_case(emit_case(c), "c.toml"), c) << "the density reads back as given";
    EXPECT_NE(error_of(replaced(small_case(), "mass = 4.188790204786391e-3",
                                "mass = 4.188790204786391e-3\ndensity = 1000.0"))
                  .find("not both"),
              std::string::npos);
    EXPECT_NE(error_of(replaced(small_case(), "mass = 4.188790204786391e-3", "")).find("species.mass: required"),
              std::string::npos);
    EXPECT_NE(error_of(by_density, {"species.0.density=-1"}).find("species.0.density = -1: must be > 0"),
              std::string::npos);
}

std::string mixture() {
    return replaced(small_case(), "[collision]\nmodel = \"brilliantov\"", R"(fraction = 0.25

[[species]]
name = "big"
mass = 1.0e-2
radius = 0.02
fraction = 0.75

[collision]
model = "brilliantov"
alpha = 0.9
beta = 0.1

[[pair]]
species = ["ice", "big"]
model = "constant"
)");
}

TEST(CaseFile, MixturesAndPairs) {
    const CaseConfig c = parse_case(mixture(), "mix.toml");
    ASSERT_EQ(c.pairs.size(), 1u);
    EXPECT_EQ(c.pairs[0].collision.model, CollisionModel::constant);
    EXPECT_EQ(c.pairs[0].collision.alpha, 0.9); // inherited from [collision]
    EXPECT_EQ(&collision_for(c, 1, 0), &c.pairs[0].collision);
    EXPECT_EQ(&collision_for(c, 0, 0), &c.collision);
    EXPECT_EQ(restitution_species(c), (std::pair<std::size_t, std::size_t>{0, 1}));

    EXPECT_NE(error_of(mixture(), {"pair.0.species=[\"ice\", \"bog\"]"}).find("\"bog\" is not a species"),
              std::string::npos);
    EXPECT_NE(error_of(mixture(), {"pair.1.species=[\"big\", \"ice\"]"}).find("already sets this pair"),
              std::string::npos);
    EXPECT_NE(error_of(mixture(), {"species.1.name=ice"}).find("must be unique"), std::string::npos);
    EXPECT_NE(error_of(mixture(), {"species.1.fraction=0.7"})
                  .find("species.fraction: the fractions sum to 0.95, "
                        "must sum to 1 (within 1e-9)"),
              std::string::npos);
    EXPECT_NE(error_of(mixture(), {"run.particles=3"}).find("gets no particle"), std::string::npos);
}

TEST(CaseFile, RestitutionGridBounds) {
    EXPECT_NE(error_of(small_case(), {"restitution.g_n_max=0.001"}).find("must be >= restitution.g_n_min"),
              std::string::npos);
    EXPECT_NE(error_of(small_case(), {"restitution.g_t_points=0"}).find("must be >= 1"), std::string::npos);
}

TEST(CaseFile, EmitParseRoundTrip) {
    const std::vector<std::string> texts = {
        small_case(), mixture(), replaced(small_case(), "dissipation = 1.0e-5", "eta1 = 3.0\neta2 = 7.0")};
    for (const std::string& t : texts) {
        const CaseConfig c = parse_case(t, "c.toml", {"run.kind=shear", "shear.rate=0.1"});
        const std::string emitted = emit_case(c);
        EXPECT_EQ(parse_case(emitted, "emitted.toml"), c) << emitted;
    }
}

TEST(CaseFile, EmitQuotesStrings) {
    const CaseConfig c =
        parse_case(small_case(), "c.toml", {"species.0.name=a\"b\\c", "contact.cache_file=x y"});
    EXPECT_EQ(c.species[0].name, "a\"b\\c");
    EXPECT_EQ(parse_case(emit_case(c), "emitted.toml"), c);
}

TEST(CaseFile, MissingFileIsInputError) {
    try {
        (void)load_case("/nonexistent/case.toml");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent/case.toml: cannot read"), std::string::npos);
    }
}

} // namespace
} // namespace roughgas
