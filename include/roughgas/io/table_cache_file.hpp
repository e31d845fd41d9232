#pragma once
// A file of persisted restitution tables ([contact] cache_file). Each entry is keyed by the full
// text of everything its table depends on (NormalTable::cache_key, TangentialTable::cache_key,
// which include the version), so a changed parameter never finds a stale entry. The whole file
// carries a checksum: a truncated or corrupt file is rejected as a whole (and then rebuilt).
//
// Layout (little-endian, as written by this machine):
//   "RGTCACHE" | u64 version | u64 entries | { u64 key_bytes, key, u64 doubles, payload }... | u64 FNV-1a of all before
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace roughgas {

class TableCacheFile {
public:
    // Reads `path` if it exists. A file that fails any check is ignored, and `rejected()` says why.
    explicit TableCacheFile(std::filesystem::path path);

    // An entry found or put is "used"; the file keeps only used entries when saved, so it holds
    // the tables of the current case and nothing stale.
    std::optional<std::vector<double>> find(const std::string& key);
    void put(const std::string& key, std::vector<double> payload);
    // Writes the file atomically (temporary, fsync, rename) unless it already holds exactly the used entries.
    void save_if_changed() const;

    const std::filesystem::path& path() const { return path_; }
    const std::string& rejected() const { return rejected_; } // empty if the file was fine or absent
    bool loaded() const { return loaded_; }

    // Serialised form, exposed for tests.
    static std::string encode(const std::map<std::string, std::vector<double>>& entries);
    static std::map<std::string, std::vector<double>> decode(const std::string& bytes); // throws on any defect

private:
    std::filesystem::path path_;
    std::map<std::string, std::vector<double>> entries_;
    std::set<std::string> used_;
    std::string rejected_;
    bool loaded_ = false;
    bool changed_ = false;
};

// Table from the cache if an entry with its key is there, else built (and put into the cache).
// `key` must be the cache key of the table `build` would make.
template <class Table>
Table load_or_build(TableCacheFile* cache, const std::string& key, const std::function<Table()>& build,
                    const std::function<Table(const std::vector<double>&)>& deserialize, bool* was_loaded = nullptr) {
    if (cache) {
        if (auto payload = cache->find(key)) {
            try {
                Table t = deserialize(*payload);
                if (was_loaded) *was_loaded = true;
                return t;
            } catch (const std::exception&) {
                // an entry that does not fit its table is as good as absent: rebuild below
            }
        }
    }
    Table t = build();
    if (cache) cache->put(key, t.serialize());
    if (was_loaded) *was_loaded = false;
    return t;
}

} // namespace roughgas
