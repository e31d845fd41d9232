#include "check_report.hpp"

#include "enskog_note.hpp"
#include "linear_stability.hpp"
#include "run/setup.hpp"
#include "run/setup_warnings.hpp"

#include <optional>

namespace roughgas::cli {

CheckReport check_case(const CaseConfig& cfg, const std::string& case_file, CaseUse use, bool print) {
    CheckReport r;
    std::optional<std::string> stability, enskog;
    r.warnings = cfg.unused;
    if (use == CaseUse::run) {
        const CasePlan plan = plan_run(cfg, case_file, 0, cfg.run.replicas);
        stability = linear_stability_note(plan.spec);
        enskog = enskog_note(plan.spec);
        r.warnings = setup_warnings(cfg, plan.spec);
    }
    if (print) {
        r.out = emit_case(cfg);
    } else {
        r.out = case_file + ": valid\n";
        if (enskog)
            r.out += case_file + ": " + *enskog + '\n';
        if (stability)
            r.out += case_file + ": " + *stability + '\n';
    }
    return r;
}

} // namespace roughgas::cli
