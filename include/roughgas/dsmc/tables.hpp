#pragma once
// The restitution tables a run needs, built once (or read from the cache file) and shared by all
// replicas, and the per-pair restitution policies that point into them.
#include "roughgas/collision/restitution_policy.hpp"
#include "roughgas/dsmc/run_spec.hpp"
#include "roughgas/dsmc/species.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace roughgas {

// One table that was built or loaded: for the caller to print (the solver never prints).
struct TableBuildInfo {
    std::string what;        // e.g. "eps^N(w) table, eq24/force, 4928 intervals"
    bool from_cache = false; // read from spec.cache_file
    double seconds = 0;      // wall time of the build or load
};

// Where persisted tables come from: the physics library cannot read files, so the
// cache file (io/table_cache_file.hpp) is reached through this interface; io/run_tables.hpp adapts it.
class TableCache {
  public:
    virtual ~TableCache() = default;
    virtual std::optional<std::vector<double>> find(const std::string& key) = 0;
    virtual void put(const std::string& key, std::vector<double> payload) = 0;
};

class RestitutionTables {
  public:
    // Builds every table the pairs of `spec` use: one eps^N(w) table per contact model (form, end)
    // of a cached viscoelastic or brilliantov pair, one eps^T table per cached brilliantov pair over
    // g_N in [table_g_min, table_g_max]; each is taken from `cache` when it holds an entry with the
    // table's key (NormalTable/TangentialTable::cache_key) that deserialises, else built and put there.
    // Nothing is built for direct pairs or when !spec.use_cache.
    static std::shared_ptr<const RestitutionTables> build(const RunSpec& spec, TableCache* cache = nullptr);

    const NormalTable* normal(const ContactModel& model) const; // nullptr if not built
    const TangentialTable* tangential(std::size_t pair) const;  // nullptr if not built
    const std::vector<TableBuildInfo>& info() const { return info_; }
    // Why the cache file was ignored, if it was (set by io/run_tables.hpp).
    const std::string& cache_rejected() const { return cache_rejected_; }
    void set_cache_rejected(std::string why) { cache_rejected_ = std::move(why); }

  private:
    std::vector<std::pair<ContactModel, std::unique_ptr<NormalTable>>> normal_;
    std::vector<std::unique_ptr<TangentialTable>> tangential_;
    std::vector<TableBuildInfo> info_;
    std::string cache_rejected_;
};

// Every concrete restitution policy (restitution_policy.hpp).
using AnyPolicy = std::variant<SmoothConstant, RoughConstant, Coulomb, ViscoelasticSmooth, Viscoelastic,
                               ViscoelasticSmoothDirect, ViscoelasticDirect, Brilliantov, BrilliantovDirect>;

// The policy of pair `pair` (index pair_index(a, b, n)), the smooth variant wherever beta = -1 for
// every impact (constant beta = -1; coulomb with beta0 = -1 or mu = 0; viscoelastic with beta = -1).
AnyPolicy make_policy(const RunSpec& spec, const RestitutionTables& tables, std::size_t pair,
                      const PairType& type);

// Mixtures whose pairs need different policy types: one variant per pair, visited per collision.
// Smooth policies among rough ones become their rough form with beta = -1 (which leaves omega
// unchanged exactly).
struct AnySmoothPolicy {
    static constexpr std::string_view name = "per-pair smooth policies";
    static constexpr bool needs_rotation = false;
    static constexpr bool needs_g_t = false;
    std::variant<SmoothConstant, ViscoelasticSmooth, ViscoelasticSmoothDirect> p;
    Coefficients operator()(double g_n, double g_t) const {
        return std::visit([&](const auto& q) { return q(g_n, g_t); }, p);
    }
};
struct AnyRoughPolicy {
    static constexpr std::string_view name = "per-pair policies";
    static constexpr bool needs_rotation = true;
    static constexpr bool needs_g_t = true;
    std::variant<RoughConstant, Coulomb, Viscoelastic, ViscoelasticDirect, Brilliantov, BrilliantovDirect> p;
    Coefficients operator()(double g_n, double g_t) const {
        return std::visit([&](const auto& q) { return q(g_n, g_t); }, p);
    }
};
// The rough form of a smooth policy (SmoothConstant -> RoughConstant with beta = -1, ...); a rough
// policy unchanged.
AnyPolicy as_rough(const AnyPolicy& p);
AnySmoothPolicy to_any_smooth(const AnyPolicy& p); // throws std::logic_error for a rough policy
AnyRoughPolicy to_any_rough(const AnyPolicy& p);

bool needs_rotation(const AnyPolicy& p);

} // namespace roughgas
