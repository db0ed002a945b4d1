#pragma once
// Honest file I/O. Output: every file is written through writeFileAtomically,
// which either leaves the complete new file or nothing (not even a temporary).
// Input: only regular files below a stated size are read, so a FIFO, a device
// such as /dev/zero or a link to one gets a message instead of a hang.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace shadelab {

// Throws InputError unless the folder of `path` exists and is writable.
void checkWritableFolder(const std::filesystem::path& path);
// 16 hex digits from the kernel's random source (getrandom), for names no
// one can predict; none when it gives no bytes.
std::optional<std::string> randomHex();

// Writes `bytes` to `path`: a temporary file created exclusively (O_EXCL,
// random name ".NAME.XXXXXXXXXXXXXXXX.tmp") in the target's folder, every
// write, fsync and close checked, then renamed over `path`. On any failure the
// temporary is removed and InputError names `path` and the reason (e.g. "File
// too large"). SIGINT, SIGTERM and SIGHUP remove a temporary being written
// before the process ends (kill -9 cannot be caught: see README).
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

// A path the process removes if SIGINT, SIGTERM or SIGHUP end it while this
// is held: a file not yet in its place (writeFileAtomically's temporary, a
// command's staged outputs) or a folder made for outputs (removed only once
// empty, after every file). The handler runs once, where the program left
// those signals' default action, then ends the process as the signal would.
// Up to kSignalSlots paths at once; more are not removed (the path is still
// written, only unguarded).
class RemovedOnSignal {
 public:
  static constexpr int kSignalSlots = 1024;
  RemovedOnSignal() = default;
  explicit RemovedOnSignal(const std::filesystem::path& path, bool folder = false);
  RemovedOnSignal(RemovedOnSignal&& other) noexcept : slot_(other.slot_) {
    other.slot_ = kSignalSlots;
  }
  RemovedOnSignal& operator=(RemovedOnSignal&& other) noexcept;
  RemovedOnSignal(const RemovedOnSignal&) = delete;
  RemovedOnSignal& operator=(const RemovedOnSignal&) = delete;
  ~RemovedOnSignal() { release(); }
  // The path is in place (or gone): a signal no longer removes it.
  void release();

 private:
  int slot_ = kSignalSlots;
};
void writeTextFile(const std::filesystem::path& path, const std::string& text);

// Input size limits, stated once. Scenes, glTF JSON and viewer scripts are
// text; buffers, GLB files and images hold binary data.
inline constexpr uint64_t kMaxTextInputBytes = uint64_t(64) << 20;   // 64 MiB
inline constexpr uint64_t kMaxBinaryInputBytes = uint64_t(1) << 30;  // 1 GiB
// Throws InputError naming `what` ("scene", "texture", ...) and `path` unless
// it is a regular file (after following links) of at most `maxBytes`.
void checkInputFile(const std::filesystem::path& path, std::string_view what, uint64_t maxBytes);
// checkInputFile, then the whole file. Opened non-blocking, checked on the
// open descriptor, so a path swapped for a FIFO after the check cannot hang.
std::string readInputFile(const std::filesystem::path& path, std::string_view what,
                          uint64_t maxBytes);

}  // namespace shadelab
