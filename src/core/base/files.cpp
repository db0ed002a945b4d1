#include "core/base/files.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <system_error>

#include "core/base/errors.h"

namespace shadelab {
namespace fs = std::filesystem;

namespace {

// Paths to remove on a signal. Fixed storage: a signal handler may not
// allocate, only unlink and rmdir (async-signal-safe) and re-raise. Pages of
// slotPath that no path was written to are never touched (no memory used).
constexpr size_t kPathBytes = 4096;
constexpr int kSlots = RemovedOnSignal::kSignalSlots;
// A slot is free, being filled, or holds a file or a folder to remove.
enum SlotState : int { kFree, kFilling, kFile, kFolder };
std::atomic<int> slotState[kSlots];
char slotPath[kSlots][kPathBytes];

void removePathsAndReraise(int signal) {
  for (int i = 0; i < kSlots; ++i)
    if (slotState[i].load() == kFile) ::unlink(slotPath[i]);
  // Newest first: a folder made inside another goes before it.
  for (int i = kSlots - 1; i >= 0; --i)
    if (slotState[i].load() == kFolder) ::rmdir(slotPath[i]);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// Installs the handler once, only where the program left the default action
// (a front end with its own SIGINT handling keeps it).
void installSignalCleanup() {
  static const bool installed = [] {
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction current {};
      if (sigaction(signal, nullptr, &current) != 0 || current.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = removePathsAndReraise;
      sigemptyset(&action.sa_mask);
      sigaction(signal, &action, nullptr);
    }
    return true;
  }();
  (void)installed;
}

std::string errnoText(int error) {
  return std::generic_category().message(error);
}

// An exclusively created temporary beside the target; removed unless released.
class TemporaryFile {
 public:
  explicit TemporaryFile(const fs::path& target) : target_(target) { create(); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (descriptor_ >= 0) ::close(descriptor_);
    if (!renamed_) ::unlink(path_.c_str());
  }

  void write(std::string_view bytes) {
    while (!bytes.empty()) {
      ssize_t written = ::write(descriptor_, bytes.data(), bytes.size());
      if (written < 0 && errno == EINTR) continue;
      if (written <= 0) fail(written < 0 ? errnoText(errno) : "nothing written");
      bytes.remove_prefix(size_t(written));
    }
  }

  // fsync so the rename never publishes a name before its data is on disk.
  void commit() {
    if (::fsync(descriptor_) != 0) fail(errnoText(errno));
    int descriptor = descriptor_;
    descriptor_ = -1;
    if (::close(descriptor) != 0) fail(errnoText(errno));
    if (::rename(path_.c_str(), target_.c_str()) != 0) fail(errnoText(errno));
    renamed_ = true;
  }

 private:
  void create() {
    for (int attempt = 0; attempt < 16 && descriptor_ < 0; ++attempt) {
      std::optional<std::string> random = randomHex();
      if (!random) fail("no random bytes for a temporary name");
      // Built by appending: GCC 12 misreports "." + std::string&& under -O2 (-Wrestrict).
      std::string name = ".";
      name += target_.filename().string();
      name += ".";
      name += *random;
      name += ".tmp";
      path_ = (target_.parent_path().empty() ? fs::path(".") : target_.parent_path()) / name;
      // Before the file exists, so no instant passes with a file the
      // handler does not know.
      guard_ = RemovedOnSignal(path_);
      // O_EXCL with O_CREAT also refuses a symbolic link planted at the name.
      descriptor_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
      if (descriptor_ < 0 && errno != EEXIST) fail(errnoText(errno));
    }
    if (descriptor_ < 0) fail("no free temporary name");
  }

  [[noreturn]] void fail(const std::string& reason) const {
    throw InputError("cannot write '" + target_.string() + "': " + reason);
  }

  fs::path target_;
  fs::path path_;
  int descriptor_ = -1;
  RemovedOnSignal guard_;
  bool renamed_ = false;
};

std::string fileKind(mode_t mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

void checkStat(const struct stat& info, const fs::path& path, std::string_view what,
               uint64_t maxBytes) {
  std::string name = std::string(what) + " '" + path.string() + "'";
  if (!S_ISREG(info.st_mode))
    throw InputError(name + " is " + fileKind(info.st_mode) + ", expected a regular file");
  if (uint64_t(info.st_size) > maxBytes)
    throw InputError(name + " is " + std::to_string(info.st_size) + " bytes, more than the " +
                     std::to_string(maxBytes >> 20) + " MiB allowed");
}

}  // namespace

RemovedOnSignal::RemovedOnSignal(const fs::path& path, bool folder) {
  installSignalCleanup();
  if (path.native().size() >= kPathBytes) return;  // not guarded (no path is this long)
  for (int i = 0; i < kSlots; ++i) {
    int expected = kFree;
    if (slotState[i].compare_exchange_strong(expected, kFilling)) {
      slot_ = i;
      break;
    }
  }
  if (slot_ == kSlots) return;
  std::memcpy(slotPath[slot_], path.c_str(), path.native().size() + 1);
  slotState[slot_].store(folder ? kFolder : kFile);
}

RemovedOnSignal& RemovedOnSignal::operator=(RemovedOnSignal&& other) noexcept {
  if (this != &other) {
    release();
    slot_ = other.slot_;
    other.slot_ = kSlots;
  }
  return *this;
}

void RemovedOnSignal::release() {
  if (slot_ < kSlots) slotState[slot_].store(kFree);
  slot_ = kSlots;
}

std::optional<std::string> randomHex() {
  uint64_t random = 0;
  if (getrandom(&random, sizeof random, 0) != sizeof random) return std::nullopt;
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(random));
  return std::string(digits);
}

void checkWritableFolder(const fs::path& path) {
  if (path.empty()) throw InputError("output path is empty");
  fs::path parent = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code error;
  if (!fs::is_directory(parent, error))
    throw InputError("output '" + path.string() + "': folder '" + parent.string() +
                     "' does not exist");
  if (::access(parent.c_str(), W_OK) != 0)
    throw InputError("output '" + path.string() + "': folder '" + parent.string() +
                     "' is not writable");
  if (fs::is_directory(path, error))
    throw InputError("output '" + path.string() + "' is a folder, expected a file name");
}

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
  checkWritableFolder(path);
  TemporaryFile temporary(path);
  temporary.write(bytes);
  temporary.commit();
}

void writeTextFile(const fs::path& path, const std::string& text) {
  writeFileAtomically(path, text);
}

void checkInputFile(const fs::path& path, std::string_view what, uint64_t maxBytes) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0)
    throw InputError(std::string(what) + " '" + path.string() + "': " + errnoText(errno));
  checkStat(info, path, what, maxBytes);
}

std::string readInputFile(const fs::path& path, std::string_view what, uint64_t maxBytes) {
  // O_NONBLOCK: opening a FIFO with no writer would otherwise block for ever.
  int descriptor = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (descriptor < 0)
    throw InputError(std::string(what) + " '" + path.string() + "': " + errnoText(errno));
  struct Closer {
    int descriptor;
    ~Closer() { ::close(descriptor); }
  } closer{descriptor};
  struct stat info {};
  if (::fstat(descriptor, &info) != 0)
    throw InputError(std::string(what) + " '" + path.string() + "': " + errnoText(errno));
  checkStat(info, path, what, maxBytes);
  std::string bytes(size_t(info.st_size), '\0');
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t got = ::read(descriptor, bytes.data() + done, bytes.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0)
      throw InputError(std::string(what) + " '" + path.string() + "': " + errnoText(errno));
    if (got == 0) break;  // shrank while reading
    done += size_t(got);
  }
  bytes.resize(done);
  return bytes;
}

}  // namespace shadelab
