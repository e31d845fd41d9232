#include "roughgas/io/run_tables.hpp"

#include "roughgas/dsmc/run.hpp"
#include "roughgas/io/table_cache_file.hpp"

namespace roughgas {
namespace {

class FileCache final : public TableCache {
  public:
    explicit FileCache(TableCacheFile& f) : f_(f) {}
    std::optional<std::vector<double>> find(const std::string& key) override { return f_.find(key); }
    void put(const std::string& key, std::vector<double> payload) override {
        f_.put(key, std::move(payload));
    }

  private:
    TableCacheFile& f_;
};

} // namespace

std::shared_ptr<const RestitutionTables> build_run_tables(const RunSpec& spec) {
    if (!spec.use_cache || spec.cache_file.empty())
        return RestitutionTables::build(spec);
    TableCacheFile file(spec.cache_file);
    FileCache cache(file);
    auto built = RestitutionTables::build(spec, &cache);
    file.save_if_changed();
    if (!file.rejected().empty()) {
        auto copy = std::const_pointer_cast<RestitutionTables>(built);
        copy->set_cache_rejected(file.rejected());
    }
    return built;
}

// Declared in dsmc/run.hpp: it lives here because it reads the cache file.
void run_replica(const RunSpec& spec, int replica, const RowSink& sink, const ProgressSink& progress) {
    const auto tables = build_run_tables(spec);
    run_replica(spec, *tables, replica, sink, progress);
}

} // namespace roughgas
