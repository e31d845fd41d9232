#include "roughgas/dsmc/tables.hpp"

#include <chrono>
#include <optional>
#include <sstream>
#include <stdexcept>

namespace roughgas {
namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

bool cached_pair(const RunSpec& spec, const PairRestitution& r) {
    if (!spec.use_cache)
        return false;
    if (const auto* v = std::get_if<ViscoelasticRestitution>(&r))
        return !v->direct;
    if (const auto* b = std::get_if<BrilliantovRestitution>(&r))
        return !b->direct;
    return false;
}

const ContactPair* contact_pair_of(const PairRestitution& r) {
    if (const auto* v = std::get_if<ViscoelasticRestitution>(&r))
        return &v->pair;
    if (const auto* b = std::get_if<BrilliantovRestitution>(&r))
        return &b->pair;
    return nullptr;
}

// io/table_cache_file.hpp's load_or_build, on the TableCache interface.
template <class Table>
Table load_or_build(TableCache* cache, const std::string& key, const std::function<Table()>& build,
                    const std::function<Table(const std::vector<double>&)>& deserialize, bool* was_loaded) {
    if (cache) {
        if (auto payload = cache->find(key)) {
            try {
                Table t = deserialize(*payload);
                *was_loaded = true;
                return t;
            } catch (const std::exception&) {
                // an entry that does not fit its table is as good as absent: rebuild below
            }
        }
    }
    Table t = build();
    if (cache)
        cache->put(key, t.serialize());
    *was_loaded = false;
    return t;
}

TangentialTableOptions tangential_options(const RunSpec& spec) {
    TangentialTableOptions opt;
    opt.g_min = spec.table_g_min;
    opt.g_max = spec.table_g_max;
    return opt;
}

} // namespace

std::shared_ptr<const RestitutionTables> RestitutionTables::build(const RunSpec& spec, TableCache* file) {
    auto out = std::make_shared<RestitutionTables>();

    out->tangential_.resize(spec.pairs.size());
    for (std::size_t p = 0; p < spec.pairs.size(); ++p) {
        const PairRestitution& r = spec.pairs[p];
        if (!cached_pair(spec, r))
            continue;
        const ContactPair& cp = *contact_pair_of(r);
        if (!out->normal(cp.model)) {
            const NormalTableOptions opt{};
            const auto t0 = std::chrono::steady_clock::now();
            bool loaded = false;
            auto table = std::make_unique<NormalTable>(load_or_build<NormalTable>(
                file, NormalTable::key_for(cp.model, opt), [&] { return NormalTable::build(cp.model, opt); },
                [&](const std::vector<double>& d) { return NormalTable::deserialize(cp.model, opt, d); },
                &loaded));
            std::ostringstream what;
            what << "eps^N(w) table " << name(cp.model.form) << "/" << name(cp.model.end) << ", "
                 << table->intervals() << " intervals";
            out->info_.push_back({what.str(), loaded, seconds_since(t0)});
            out->normal_.emplace_back(cp.model, std::move(table));
        }
        if (std::holds_alternative<BrilliantovRestitution>(r)) {
            const TangentialTableOptions opt = tangential_options(spec);
            const auto t0 = std::chrono::steady_clock::now();
            bool loaded = false;
            auto table = std::make_unique<TangentialTable>(load_or_build<TangentialTable>(
                file, TangentialTable::key_for(cp, opt), [&] { return TangentialTable::build(cp, opt); },
                [&](const std::vector<double>& d) { return TangentialTable::deserialize(cp, opt, d); },
                &loaded));
            std::ostringstream what;
            what << "eps^T(g_N, g_T) table of pair " << p << ", g_N in [" << opt.g_min << ", " << opt.g_max
                 << "]";
            out->info_.push_back({what.str(), loaded, seconds_since(t0)});
            out->tangential_[p] = std::move(table);
        }
    }
    return out;
}

const NormalTable* RestitutionTables::normal(const ContactModel& model) const {
    for (const auto& [m, t] : normal_)
        if (m == model)
            return t.get();
    return nullptr;
}

const TangentialTable* RestitutionTables::tangential(std::size_t pair) const {
    return pair < tangential_.size() ? tangential_[pair].get() : nullptr;
}

AnyPolicy make_policy(const RunSpec& spec, const RestitutionTables& tables, std::size_t pair,
                      const PairType& type) {
    const PairRestitution& r = spec.pairs.at(pair);
    const bool cached = cached_pair(spec, r);
    return std::visit(
        [&](const auto& m) -> AnyPolicy {
            using M = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<M, ConstantRestitution>) {
                if (m.beta == -1.0)
                    return make_smooth_constant(m.alpha);
                return make_rough_constant(m.alpha, m.beta);
            } else if constexpr (std::is_same_v<M, CoulombRestitution>) {
                if (m.beta0 == -1.0 || m.mu == 0.0)
                    return make_smooth_constant(m.alpha); // beta = -1 always
                return make_coulomb(m.alpha, m.beta0, m.mu, type.pc.kappa);
            } else if constexpr (std::is_same_v<M, ViscoelasticRestitution>) {
                if (cached) {
                    const NormalTable* t = tables.normal(m.pair.model);
                    if (!t)
                        throw std::logic_error("make_policy: eps^N table not built");
                    if (m.beta == -1.0)
                        return make_viscoelastic_smooth(*t, m.pair);
                    return make_viscoelastic(*t, m.pair, m.beta);
                }
                if (m.beta == -1.0)
                    return make_viscoelastic_smooth_direct(m.pair, spec.contact_tolerance);
                return make_viscoelastic_direct(m.pair, m.beta, spec.contact_tolerance);
            } else {
                static_assert(std::is_same_v<M, BrilliantovRestitution>);
                if (cached) {
                    const NormalTable* n = tables.normal(m.pair.model);
                    const TangentialTable* t = tables.tangential(pair);
                    if (!n || !t)
                        throw std::logic_error("make_policy: restitution tables not built");
                    return make_brilliantov(*n, *t, m.pair);
                }
                return make_brilliantov_direct(m.pair, spec.contact_tolerance);
            }
        },
        r);
}

bool needs_rotation(const AnyPolicy& p) {
    return std::visit([](const auto& q) { return std::decay_t<decltype(q)>::needs_rotation; }, p);
}

AnySmoothPolicy to_any_smooth(const AnyPolicy& p) {
    return std::visit(
        [](const auto& q) -> AnySmoothPolicy {
            using Q = std::decay_t<decltype(q)>;
            if constexpr (Q::needs_rotation) {
                throw std::logic_error("to_any_smooth: rough policy");
            } else {
                return {q};
            }
        },
        p);
}

AnyPolicy as_rough(const AnyPolicy& p) {
    return std::visit(
        [](const auto& q) -> AnyPolicy {
            using Q = std::decay_t<decltype(q)>;
            if constexpr (std::is_same_v<Q, SmoothConstant>) {
                return make_rough_constant(q.normal.alpha, -1.0);
            } else if constexpr (std::is_same_v<Q, ViscoelasticSmooth>) {
                return Viscoelastic{{q.normal, {-1.0}}};
            } else if constexpr (std::is_same_v<Q, ViscoelasticSmoothDirect>) {
                return ViscoelasticDirect{{q.normal, {-1.0}}};
            } else {
                return q;
            }
        },
        p);
}

AnyRoughPolicy to_any_rough(const AnyPolicy& p) {
    return std::visit(
        [](const auto& q) -> AnyRoughPolicy {
            using Q = std::decay_t<decltype(q)>;
            if constexpr (Q::needs_rotation) {
                return {q};
            } else {
                throw std::logic_error("to_any_rough: smooth policy (use as_rough first)");
            }
        },
        as_rough(p));
}

} // namespace roughgas
