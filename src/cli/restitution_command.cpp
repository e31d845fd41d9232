// roughgas restitution CASE.toml --out DIR: tabulates the contact model on the [restitution] grid
// with the direct integrator (contact_integrator.hpp), writing DIR/normal.csv and DIR/tangential.csv.
//
// Order of work: validate the case and the output directory, compute everything, then create DIR
// and write both files atomically, so invalid input or a failed integration writes nothing.
#include "commands.hpp"

#include "roughgas/core/available_cpus.hpp"
#include "roughgas/dsmc/run_spec.hpp"

#include <omp.h>
#include "parallel_for.hpp"
#include "quasistatic_warning.hpp"
#include "restitution_tables.hpp"

#include "roughgas/contact/contact_integrator.hpp"
#include "roughgas/io/case_file.hpp"
#include "roughgas/io/csv_writer.hpp"
#include "roughgas/io/restitution_csv.hpp"
#include "roughgas/io/table_cache_file.hpp"
#include "roughgas/restitution/normal_table.hpp"
#include "roughgas/restitution/tangential_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <exception>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace roughgas::cli {
namespace {

namespace fs = std::filesystem;

struct RestitutionOptions {
    std::string case_file;
    std::string out;
    std::vector<std::string> sets;
    bool force = false;
    int threads = 0; // 0: OpenMP's default
};

constexpr std::array<std::string_view, 2> output_files{"normal.csv", "tangential.csv"};

// Never overwrite earlier results by accident: that is an input error, reported before any work.
void check_output_dir(const fs::path& dir, bool force) {
    if (fs::exists(dir) && !fs::is_directory(dir)) {
        throw InputError(dir.string(), "--out", "--out " + dir.string() + ": exists and is not a directory");
    }
    for (std::string_view f : output_files) {
        if (!force && fs::exists(dir / f)) {
            throw InputError(dir.string(), "--out",
                             fmt::format("--out {}: {} exists (use --force to overwrite)", dir.string(), f));
        }
    }
}

// n points from lo to hi, both ends exact (n = 1: lo only).
std::vector<double> grid(double lo, double hi, std::int64_t n, GridSpacing spacing) {
    std::vector<double> g(static_cast<std::size_t>(n));
    for (std::int64_t k = 0; k < n; ++k) {
        const double t = n > 1 ? static_cast<double>(k) / static_cast<double>(n - 1) : 0.0;
        g[k] = spacing == GridSpacing::log ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t;
    }
    if (n > 1)
        g.back() = hi;
    return g;
}

CsvProvenance provenance(const RestitutionOptions& o, const CaseConfig& cfg, const ContactPair& pc) {
    const auto [i, j] = restitution_species(cfg);
    CsvProvenance p;
    p.case_file = o.case_file;
    p.overrides = o.sets;
    p.resolved_case = emit_case(cfg);
    p.notes = {
        fmt::format(
            "pair: species \"{}\" with \"{}\": m_eff = {} kg, R_eff = {} m, kappa = {}",
            cfg.species[i].name, cfg.species[j].name, pc.m_eff, pc.R_eff, pc.kappa),
        fmt::format("contact: {}, end = {}, rho = {} m^-1/2 s^-2, A = {} s, mu = {}, zeta0 = "
                    "{} m",
                    name(pc.model.form), name(pc.model.end), pc.rho, pc.A, pc.mu, pc.zeta0),
        fmt::format("direct integration, tolerance rel = {:.3g}, abs = {:.3g}", cfg.contact.tolerance.rel,
                    cfg.contact.tolerance.abs),
        si_unit_system_note, // the contact model's [material] is in SI
    };
    return p;
}

int run_restitution(const RestitutionOptions& o) {
    const CaseConfig cfg = load_case(o.case_file, o.sets, CaseUse::restitution);
    const fs::path dir(o.out);
    check_output_dir(dir, o.force);

    const auto [i, j] = restitution_species(cfg);
    const ContactPair pc = contact_pair(cfg, i, j);
    const Tolerance tol = cfg.contact.tolerance;
    const RestitutionGridConfig& gc = cfg.restitution;
    const std::vector<double> g_n = grid(gc.g_n_min, gc.g_n_max, gc.g_n_points, gc.spacing);
    const std::vector<double> g_t = grid(gc.g_t_min, gc.g_t_max, gc.g_t_points, gc.spacing);
    const int threads = o.threads > 0 ? o.threads : default_threads();
    omp_set_num_threads(threads); // the table builds use the same threads
    warn_if_not_quasistatic(cfg, i, j, g_n, "[restitution] grid", std::cerr);

    std::vector<ContactResult> normal(g_n.size());
    parallel_for(g_n.size(), threads,
                 [&](std::size_t k) { normal[k] = integrate_normal_contact(pc, g_n[k], tol); });
    std::vector<ContactResult> tangential(g_n.size() * g_t.size()); // row-major: g_N outer, g_T inner
    parallel_for(tangential.size(), threads, [&](std::size_t k) {
        tangential[k] = integrate_contact(pc, g_n[k / g_t.size()], g_t[k % g_t.size()], tol);
    });

    std::optional<CachedTables> tables;
    if (cfg.contact.cache) tables.emplace(load_or_build_tables(cfg, pc));

    const CsvProvenance prov = provenance(o, cfg, pc);
    std::vector<std::string> normal_names = column_names(normal_columns);
    std::vector<std::string> tangential_names = column_names(tangential_columns);
    if (tables) {
        normal_names.emplace_back(normal_table_column.name);
        tangential_names.emplace_back(tangential_table_column.name);
    }
    CsvWriter normal_csv(normal_names, prov);
    for (std::size_t k = 0; k < g_n.size(); ++k) {
        const ContactResult& r = normal[k];
        std::vector<double> row{g_n[k], pc.w(g_n[k]), r.eps_n, r.duration, r.max_compression};
        if (tables) row.push_back(tables->normal.eps_n(pc.w(g_n[k])));
        normal_csv.add_row(row);
    }
    CsvWriter tangential_csv(tangential_names, prov);
    for (std::size_t k = 0; k < tangential.size(); ++k) {
        const ContactResult& r = tangential[k];
        const double gn = g_n[k / g_t.size()], gt = g_t[k % g_t.size()];
        std::vector<double> row{gn, gt, r.eps_t, r.beta, static_cast<double>(r.breaks)};
        if (tables) row.push_back(tables->tangential.eps_t(gn, gt));
        tangential_csv.add_row(row);
    }

    fs::create_directories(dir);
    normal_csv.write(dir / output_files[0]);
    tangential_csv.write(dir / output_files[1]);
    std::cout << fmt::format("roughgas restitution: wrote {} ({} rows) and {} ({} rows)\n",
                             (dir / output_files[0]).string(), normal_csv.rows(),
                             (dir / output_files[1]).string(), tangential_csv.rows());
    return exit_ok;
}

} // namespace

Subcommand add_restitution_command(CLI::App& parent) {
    auto o = std::make_shared<RestitutionOptions>();
    CLI::App* app = parent.add_subcommand(
        "restitution",
        "tabulate eps_N(g_N) and eps_T(g_N, g_T) of the case's contact model on the [restitution] grid");
    app->add_option("CASE", o->case_file, "case file (TOML)")->required();
    app->add_option("--out", o->out, "output directory (normal.csv, tangential.csv)")->required();
    add_set_option(*app, o->sets);
    app->add_flag("--force", o->force, "overwrite normal.csv and tangential.csv in an existing DIR");
    app->add_option("--threads", o->threads, "threads (default: the CPUs this process may use)")->check(positive());
    return {app, [o] { return run_restitution(*o); }};
}

} // namespace roughgas::cli
