#pragma once
// The binary encoding of the files roughgas writes for itself to read back (the restitution table
// cache, io/table_cache_file.hpp; checkpoints, io/checkpoint_file.hpp; the engine's state,
// dsmc/engine.hpp): fixed-width words in this machine's byte order, doubles as their 64 bits (a
// checkpoint must give back every bit), strings and arrays prefixed by their length. The files
// are for the machine that wrote them: each starts with a magic word and a format version, and a
// machine of the other byte order reads a wrong version and refuses the file.
//
// In the physics library (no {fmt}, no parser), since the engine encodes its own state.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace roughgas {

// FNV-1a, 64 bits: the checksum of those files (catches truncation and flipped bytes; not a
// defence against deliberate edits). About 1 GB/s.
inline std::uint64_t fnv1a(const char* data, std::size_t n) {
    std::uint64_t h = 1469598103934665603ull;
    for (std::size_t i = 0; i < n; ++i) {
        h ^= static_cast<unsigned char>(data[i]);
        h *= 1099511628211ull;
    }
    return h;
}

class ByteWriter {
  public:
    void reserve(std::size_t bytes) { out_.reserve(out_.size() + bytes); }
    // A trivially copyable scalar (integers, double, bool), its bytes as in memory.
    template <class T> void put(T v) {
        static_assert(std::is_arithmetic_v<T>, "scalars only: structs have padding");
        char b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));
        out_.append(b, sizeof(T));
    }
    void u64(std::uint64_t v) { put(v); }
    void f64(double v) { put(v); }
    void str(std::string_view s) {
        u64(s.size());
        out_.append(s);
    }
    // An array of doubles: its length, then the values.
    void f64s(std::span<const double> v) {
        u64(v.size());
        out_.append(reinterpret_cast<const char*>(v.data()), v.size_bytes());
    }
    void raw(std::string_view s) { out_.append(s); }
    std::size_t size() const { return out_.size(); }
    const std::string& bytes() const { return out_; }
    std::string take() { return std::move(out_); }

  private:
    std::string out_;
};

// Reads what ByteWriter wrote; any read past the end throws std::runtime_error("truncated").
class ByteReader {
  public:
    explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}
    void need(std::size_t n) const {
        if (n > bytes_.size() - pos_)
            throw std::runtime_error("truncated");
    }
    template <class T> T get() {
        static_assert(std::is_arithmetic_v<T>, "scalars only");
        need(sizeof(T));
        T v;
        std::memcpy(&v, bytes_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return v;
    }
    std::uint64_t u64() { return get<std::uint64_t>(); }
    double f64() { return get<double>(); }
    // A count of items of at least `item_bytes` bytes each that must still fit in the input: a
    // corrupt length fails here rather than in a huge allocation.
    std::size_t count(std::size_t item_bytes) {
        const std::uint64_t n = u64();
        if (item_bytes > 0 && n > (bytes_.size() - pos_) / item_bytes)
            throw std::runtime_error("truncated");
        return static_cast<std::size_t>(n);
    }
    std::string_view raw(std::size_t n) {
        need(n);
        const std::string_view s = bytes_.substr(pos_, n);
        pos_ += n;
        return s;
    }
    std::string str() { return std::string(raw(count(1))); }
    std::vector<double> f64s() {
        std::vector<double> v(count(sizeof(double)));
        if (!v.empty()) // memcpy to a null pointer is undefined even for 0 bytes (UBSan)
            std::memcpy(v.data(), raw(v.size() * sizeof(double)).data(), v.size() * sizeof(double));
        return v;
    }
    std::size_t pos() const { return pos_; }
    std::size_t remaining() const { return bytes_.size() - pos_; }

  private:
    std::string_view bytes_;
    std::size_t pos_ = 0;
};

} // namespace roughgas
