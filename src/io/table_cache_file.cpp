// Reading and writing the restitution table cache (see table_cache_file.hpp).
#include "roughgas/io/table_cache_file.hpp"

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

std::uint64_t fnv1a(const char* data, std::size_t n) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < n; ++i) {
        h ^= static_cast<unsigned char>(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}

void put_u64(std::string& out, std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }

struct Reader {
    const std::string& bytes;
    std::size_t pos = 0;
    void need(std::size_t n) const {
        if (n > bytes.size() - pos) throw std::runtime_error("truncated");
    }
    std::uint64_t u64() {
        need(8);
        std::uint64_t v;
        std::memcpy(&v, bytes.data() + pos, 8);
        pos += 8;
        return v;
    }
};

} // namespace

std::string TableCacheFile::encode(const std::map<std::string, std::vector<double>>& entries) {
    std::string out(magic, sizeof magic);
    put_u64(out, format_version);
    put_u64(out, entries.size());
    for (const auto& [key, payload] : entries) {
        put_u64(out, key.size());
        out += key;
        put_u64(out, payload.size());
        out.append(reinterpret_cast<const char*>(payload.data()), payload.size() * sizeof(double));
    }
    put_u64(out, fnv1a(out.data(), out.size()));
    return out;
}

std::map<std::string, std::vector<double>> TableCacheFile::decode(const std::string& bytes) {
    if (bytes.size() < sizeof magic + 24 || std::memcmp(bytes.data(), magic, sizeof magic) != 0)
        throw std::runtime_error("not a roughgas table cache (bad header)");
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + bytes.size() - 8, 8);
    if (stored != fnv1a(bytes.data(), bytes.size() - 8)) throw std::runtime_error("checksum mismatch (corrupt or truncated)");
    Reader r{bytes, sizeof magic};
    if (r.u64() != format_version) throw std::runtime_error("unknown format version");
    const std::uint64_t n = r.u64();
    std::map<std::string, std::vector<double>> entries;
    for (std::uint64_t e = 0; e < n; ++e) {
        const std::uint64_t key_bytes = r.u64();
        r.need(key_bytes);
        std::string key = bytes.substr(r.pos, key_bytes);
        r.pos += key_bytes;
        const std::uint64_t count = r.u64();
        if (count > (bytes.size() - r.pos) / sizeof(double)) throw std::runtime_error("truncated");
        std::vector<double> payload(count);
        if (count > 0) // memcpy from or to a null pointer is undefined even for 0 bytes (UBSan)
            std::memcpy(payload.data(), bytes.data() + r.pos, count * sizeof(double));
        r.pos += count * sizeof(double);
        entries.emplace(std::move(key), std::move(payload));
    }
    if (r.pos != bytes.size() - 8) throw std::runtime_error("trailing bytes");
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
