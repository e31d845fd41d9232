#pragma once
// Output files appear complete or not at all: a crash, a full disk or a kill
// mid-write leaves the previous file (or none), never a truncated one.
#include <filesystem>
#include <string_view>

namespace roughgas {

// Writes `contents` to a file in the same directory as `path` (so the rename cannot cross file
// systems), fsyncs it, renames it over `path` and fsyncs the directory. The file is unnamed while
// it is written (Linux O_TMPFILE) and named `path.tmp.<pid>` only once complete, so a process
// killed mid-write leaves nothing behind; where the file system has no unnamed files it is named
// `path.tmp.<pid>` from the start. On failure the temporary file is removed and std::system_error
// is thrown; `path` is then untouched.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

// For a file another library writes (HDF5): `tmp`, complete and closed, is fsynced, renamed over
// `path` and the directory fsynced. On failure `tmp` is removed and std::system_error is thrown.
void publish_file_atomically(const std::filesystem::path& tmp, const std::filesystem::path& path);

// The temporary name used for `path` by this process.
std::filesystem::path temporary_path(const std::filesystem::path& path);

} // namespace roughgas
