#include "io/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "io/output_guard.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

std::string sizeText(std::uintmax_t bytes) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.1f MiB", static_cast<double>(bytes) / (1 << 20));
  return buffer;
}

void checkStat(const struct stat& st, const std::filesystem::path& path, const std::string& kind,
               std::uintmax_t maxBytes) {
  if (!S_ISREG(st.st_mode))
    throw InputError("cannot read " + kind + " " + path.string() + ": it is " + fileTypeName(st.st_mode) +
                     ", not a regular file");
  if (static_cast<std::uintmax_t>(st.st_size) > maxBytes)
    throw InputError("cannot read " + kind + " " + path.string() + ": it is " +
                     sizeText(static_cast<std::uintmax_t>(st.st_size)) + "; Kerf reads " + kind +
                     " files of up to " + sizeText(maxBytes));
}

}  // namespace

const char* fileTypeName(unsigned mode) {
  if (S_ISDIR(mode)) return "a folder";
  if (S_ISFIFO(mode)) return "a pipe (FIFO)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

std::uintmax_t checkInputFile(const std::filesystem::path& path, const std::string& kind,
                              std::uintmax_t maxBytes) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    throw InputError("cannot open " + kind + " " + path.string() + ": " +
                     (errno == ENOENT ? "file not found" : std::strerror(errno)));
  checkStat(st, path, kind, maxBytes);
  rememberInputFile(path);  // an output of the same command must not replace it (io/output_guard.hpp)
  return static_cast<std::uintmax_t>(st.st_size);
}

std::string readInputFile(const std::filesystem::path& path, const std::string& kind,
                          std::uintmax_t maxBytes) {
  checkInputFile(path, kind, maxBytes);
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw InputError("cannot open " + kind + " " + path.string() + ": " + std::strerror(errno));
  std::string bytes;
  try {
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw InputError("cannot read " + kind + " " + path.string());
    checkStat(st, path, kind, maxBytes);
    bytes.resize(static_cast<std::size_t>(st.st_size));
    std::size_t done = 0;
    while (done < bytes.size()) {
      const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) throw InputError("cannot read " + kind + " " + path.string() + ": " + std::strerror(errno));
      if (n == 0) break;  // the file shrank while being read
      done += static_cast<std::size_t>(n);
    }
    bytes.resize(done);
  } catch (...) {
    ::close(fd);
    throw;
  }
  ::close(fd);
  return bytes;
}

}  // namespace kerf
