// Reading and writing the restitution table cache (see table_cache_file.hpp).
#include "roughgas/io/table_cache_file.hpp"

#include "roughgas/core/bytes.hpp"
#include "roughgas/io/atomic_file.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace roughgas {
namespace {

constexpr char magic[8] = {'R', 'G', 'T', 'C', 'A', 'C', 'H', 'E'};
constexpr std::uint64_t format_version = 1;

} // namespace

std::string TableCacheFile::encode(const std::map<std::string, std::vector<double>>& entries) {
    ByteWriter w;
    w.raw(std::string_view(magic, sizeof magic));
    w.u64(format_version);
    w.u64(entries.size());
    for (const auto& [key, payload] : entries) {
        w.str(key);
        w.f64s(payload);
    }
    w.u64(fnv1a(w.bytes().data(), w.size()));
    return w.take();
}

std::map<std::string, std::vector<double>> TableCacheFile::decode(const std::string& bytes) {
    if (bytes.size() < sizeof magic + 24 || std::memcmp(bytes.data(), magic, sizeof magic) != 0)
        throw std::runtime_error("not a roughgas table cache (bad header)");
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (stored != fnv1a(bytes.data(), bytes.size() - 8)) throw std::runtime_error("checksum mismatch (corrupt or truncated)");
    ByteReader r(std::string_view(bytes).substr(0, bytes.size() - 8));
    r.raw(sizeof magic);
    if (r.u64() != format_version) throw std::runtime_error("unknown format version");
    const std::uint64_t n = r.u64();
    std::map<std::string, std::vector<double>> entries;
    for (std::uint64_t e = 0; e < n; ++e) {
        std::string key = r.str();
        entries.emplace(std::move(key), r.f64s());
    }
    if (r.remaining() != 0) throw std::runtime_error("trailing bytes");
    return entries;
}

TableCacheFile::TableCacheFile(std::filesystem::path path) : path_(std::move(path)) {
    std::ifstream in(path_, std::ios::binary);
    if (!in) return; // absent: start empty
    std::ostringstream buf;
    buf << in.rdbuf();
    try {
        entries_ = decode(buf.str());
        loaded_ = true;
    } catch (const std::exception& e) {
        rejected_ = e.what();
        entries_.clear();
        changed_ = true; // rewrite it even if nothing new is put
    }
}

std::optional<std::vector<double>> TableCacheFile::find(const std::string& key) {
    const auto it = entries_.find(key);
    if (it == entries_.end()) return std::nullopt;
    used_.insert(key);
    return it->second;
}

void TableCacheFile::put(const std::string& key, std::vector<double> payload) {
    entries_[key] = std::move(payload);
    used_.insert(key);
    changed_ = true;
}

void TableCacheFile::save_if_changed() const {
    if (!changed_ && used_.size() == entries_.size()) return;
    std::map<std::string, std::vector<double>> keep;
    for (const auto& key : used_) keep.emplace(key, entries_.at(key));
    if (path_.has_parent_path()) std::filesystem::create_directories(path_.parent_path());
    write_file_atomically(path_, encode(keep));
}

} // namespace roughgas
