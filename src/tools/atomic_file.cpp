// write_atomically (cli.hpp): a file is either written whole or left as it
// was. The text goes to a temporary file beside the target, created
// exclusively (O_EXCL, O_NOFOLLOW: never an existing file or a link planted
// there) under an unpredictable name, synced to disk, then renamed over the
// target. The temporary file is removed on every error, and on SIGINT,
// SIGTERM and SIGHUP while it exists. A target that exists and is not a
// regular file (a device such as /dev/null, a FIFO) is written directly:
// renaming over it would replace the device node by a file. A symbolic link
// to a file has that file replaced, not the link.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <random>

#include "cli.hpp"

namespace kvd::cli {

namespace {

// The temporary file being written, for the signal handler: a fixed buffer,
// since a handler may only make async-signal-safe calls (unlink, raise).
char pending_path[4096];
volatile std::sig_atomic_t pending = 0;
constexpr int removal_signals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_pending(int sig) {
  if (pending) unlink(pending_path);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// Installs the handler while a temporary file exists; restores the old ones.
class Pending_file {
public:
  explicit Pending_file(const std::string& path) {
    if (path.size() >= sizeof pending_path) return;  // too long to register: removed on errors only
    std::memcpy(pending_path, path.c_str(), path.size() + 1);
    pending = 1;
    for (std::size_t i = 0; i < std::size(removal_signals); ++i) old_[i] = std::signal(removal_signals[i], remove_pending);
  }
  ~Pending_file() {
    if (!pending) return;
    for (std::size_t i = 0; i < std::size(removal_signals); ++i) std::signal(removal_signals[i], old_[i]);
    pending = 0;
  }
  Pending_file(const Pending_file&) = delete;
  Pending_file& operator=(const Pending_file&) = delete;

private:
  void (*old_[std::size(removal_signals)])(int) = {};
};

std::string random_suffix() {
  std::random_device device;
  const std::uint64_t bits = (std::uint64_t(device()) << 32) ^ device();
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(bits));
  return hex;
}

// Writes all of `text` to fd, and syncs it if `sync`; false on any error.
bool write_all(int fd, const std::string& text, bool sync) {
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return !sync || fsync(fd) == 0;
}

}  // namespace

void write_atomically(const std::string& command, const std::string& path, const std::string& text) {
  const auto fail = [&](const std::string& why) { throw Usage_error("kvd " + command + ": cannot write " + path + " (" + why + ")"); };
  struct stat st;
  const bool exists = ::stat(path.c_str(), &st) == 0;
  if (exists && !S_ISREG(st.st_mode)) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) fail(std::strerror(errno));
    const bool written = write_all(fd, text, false);
    const int write_errno = errno;
    if (::close(fd) != 0 || !written) fail(std::strerror(written ? errno : write_errno));
    return;
  }
  std::error_code link_error;
  const std::filesystem::path target = exists && std::filesystem::is_symlink(path, link_error)
                                           ? std::filesystem::canonical(path)
                                           : std::filesystem::path(path);
  const std::filesystem::path folder = target.parent_path().empty() ? "." : target.parent_path();
  std::string temp;
  int fd = -1;
  for (int attempt = 0; attempt < 8 && fd < 0; ++attempt) {
    temp = (folder / ("." + target.filename().string() + ".tmp-" + random_suffix())).string();
    fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) fail(std::strerror(errno));
  }
  if (fd < 0) fail("no unused temporary name");
  Pending_file guard(temp);
  const bool written = write_all(fd, text, true);
  const int write_errno = errno;
  if (::close(fd) != 0 || !written) {
    ::unlink(temp.c_str());
    fail(std::strerror(written ? errno : write_errno));
  }
  if (std::rename(temp.c_str(), target.c_str()) != 0) {
    const int e = errno;
    ::unlink(temp.c_str());
    fail(std::strerror(e));
  }
  // The rename itself is durable once the folder is synced.
  if (const int dir = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC); dir >= 0) {
    fsync(dir);
    ::close(dir);
  }
}

}  // namespace kvd::cli
