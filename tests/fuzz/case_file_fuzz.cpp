// libFuzzer target for the case-file parser and validator: any input must end in
// either a valid CaseConfig or an InputError that names the file; nothing else (no other exception,
// no crash, no sanitizer report). A valid case must also survive the round trip through its
// resolved TOML (emit_case) unchanged, and turn into a RunSpec whose numbers are finite.
//
//   scripts/fuzz.sh [SECONDS]     (clang + libFuzzer + ASan/UBSan; seed corpus: cases/*.toml)
#include "roughgas/io/case_file.hpp"
#include "roughgas/io/run_spec_from_case.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace {

void fail(const char* what, const std::string& detail) {
    std::fprintf(stderr, "case_file_fuzz: %s\n%s\n", what, detail.c_str());
    std::abort();
}

void check_finite(const roughgas::RunSpec& s) {
    bool ok = std::isfinite(s.density) && std::isfinite(s.end) && std::isfinite(s.histogram_max);
    for (const auto& sp : s.species)
        ok = ok && std::isfinite(sp.mass) && std::isfinite(sp.radius) && std::isfinite(sp.inertia) &&
             std::isfinite(sp.fraction) && std::isfinite(sp.temperature) &&
             std::isfinite(sp.rotational_temperature);
    for (double t : s.output_times)
        ok = ok && std::isfinite(t);
    if (!ok)
        fail("a validated case holds a non-finite number", "");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (const roughgas::CaseUse use : {roughgas::CaseUse::run, roughgas::CaseUse::restitution}) {
        try {
            const roughgas::CaseConfig c = roughgas::parse_case(text, "fuzz.toml", {}, use);
            const std::string emitted = roughgas::emit_case(c);
            roughgas::CaseConfig again;
            try {
                again = roughgas::parse_case(emitted, "emitted.toml", {}, use);
            } catch (const roughgas::InputError& e) {
                fail("the resolved case of a valid case is invalid", std::string(e.what()) + "\n" + emitted);
            }
            if (!(again == c))
                fail("the resolved case does not read back the same", emitted);
            if (use == roughgas::CaseUse::run && c.run.kind == roughgas::RunKind::cooling)
                check_finite(roughgas::run_spec_from_case(c));
        } catch (const roughgas::InputError& e) {
            if (e.file() != "fuzz.toml")
                fail("an input error that does not name the file", e.what());
        }
    }
    return 0;
}
