// `roughgas run` in this process (commands.hpp, run_in_one_process): the same pipeline, files and
// bytes as the command line, with the GIL released while it runs. SIGINT and SIGTERM stop it as they
// stop the command (stop_signals.hpp): a checkpoint and the CSV so far, and the status 128 + the
// signal, which the package turns into KeyboardInterrupt.
#include "bindings.hpp"
#include "case_source.hpp"

#include "commands.hpp"
#include "run/setup.hpp"

#include <pybind11/stl.h>

#include <optional>

namespace py = pybind11;

namespace roughgas::python {

void bind_run(py::module_& m) {
    m.def(
        "run_case",
        [](const CaseSource& c, const std::string& out, int threads, bool quiet, bool force,
           std::optional<std::uint64_t> seed, double checkpoint_every) {
            cli::RunOptions o;
            o.case_file = c.name;
            o.case_text = c.text;
            o.sets = c.sets;
            o.out = out;
            o.threads = threads;
            o.quiet = quiet;
            o.force = force;
            o.seed_given = seed.has_value();
            o.seed = seed.value_or(0);
            o.checkpoint_every = checkpoint_every;
            o.checkpoint_every_given = checkpoint_every > 0;
            py::gil_scoped_release release;
            return cli::run_in_one_process(o);
        },
        py::arg("case"), py::arg("out"), py::arg("threads"), py::arg("quiet"), py::arg("force"), py::arg("seed"),
        py::arg("checkpoint_every"), "roughgas run CASE --out OUT ...; returns the exit status");
    m.def(
        "resume_run",
        [](const std::string& dir, int threads, bool quiet) {
            cli::RunOptions o;
            o.resume = dir;
            o.threads = threads;
            o.quiet = quiet;
            py::gil_scoped_release release;
            return cli::run_in_one_process(o);
        },
        py::arg("dir"), py::arg("threads"), py::arg("quiet"), "roughgas run --resume DIR; returns the exit status");
}

} // namespace roughgas::python
