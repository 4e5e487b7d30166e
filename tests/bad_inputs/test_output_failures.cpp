// Outputs that cannot be written (catalogue in docs/reliability.md): a full disk, a folder that does not
// exist or is a file. The message names the file; the file that was there before is unchanged (saves are
// atomic) and no temporary file is left. A full disk is simulated with RLIMIT_FSIZE, which makes writes
// past the limit fail with EFBIG as ENOSPC would (the tests run as root, so permissions cannot be used).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <random>

#include "bad_input_files.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/project.hpp"
#include "run_cli.hpp"
#include "util/error.hpp"

using namespace kerf;
using namespace kerf::bad;

namespace {

class FullDisk {
 public:
  explicit FullDisk(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    previous_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit = saved_;
    limit.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &limit);
  }
  ~FullDisk() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_);
  }

 private:
  rlimit saved_{};
  void (*previous_)(int) = SIG_DFL;
};

fs::path folder(const std::string& name) {
  const fs::path dir = fs::path(KERF_TEST_ARTIFACTS) / "output_failures" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::size_t filesIn(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

}  // namespace

TEST(OutputFailures, FullDiskKeepsThePreviousProject) {
  const fs::path dir = folder("full_disk_project");
  const fs::path file = dir / "work.kerf";
  saveProject(Project(), file);
  const std::string before = readBytes(file);
  Project bigger;
  for (int i = 0; i < 200; ++i) bigger.annotations.traces.push_back({FaceId::A, {{1, 1}, {2, 2}, {3, 3}}, i});
  std::string message;
  {
    const FullDisk full(before.size() + 100);
    message = errorOf([&] { saveProject(bigger, file); });
  }
  EXPECT_NE(message.find("cannot write " + file.string() + " (disk full?)"), std::string::npos) << message;
  EXPECT_EQ(readBytes(file), before);
  EXPECT_EQ(filesIn(dir), 1u) << "a temporary file was left";
}

// Every image format Kerf writes. libpng, as OpenImageIO drives it, does not report a failed write, so a
// PNG is checked for its end before it replaces the target (verifyWrittenImage, io/image.cpp).
TEST(OutputFailures, FullDiskImageWrite) {
  for (const char* extension : {".png", ".tif", ".exr"}) {
    const fs::path dir = folder(std::string("full_disk_image") + extension);
    const fs::path file = dir / (std::string("face") + extension);
    Image noisy(256, 256, 3);
    std::mt19937 random(3);  // noise: no format compresses it below the limit
    for (float& v : noisy.pixels) v = std::uniform_real_distribution<float>(0, 1)(random);
    std::string message;
    {
      const FullDisk full(4096);
      message = errorOf([&] { writeImage(file, noisy); });
    }
    EXPECT_NE(message.find("cannot write " + file.string()), std::string::npos)
        << extension << ": " << message;
    EXPECT_EQ(filesIn(dir), 0u) << extension;
  }
}

TEST(OutputFailures, FolderThatIsAFile) {
  const fs::path dir = folder("folder_is_a_file");
  writeText(dir / "notes.txt", "not a folder");
  const std::string message = errorOf([&] { saveProject(Project(), dir / "notes.txt" / "work.kerf"); });
  EXPECT_NE(message.find("cannot write " + (dir / "notes.txt" / "work.kerf").string()), std::string::npos)
      << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
}

TEST(OutputFailures, CliReportsAFullDisk) {
  const fs::path dir = folder("full_disk_cli");
  saveProject(Project(), dir / "demo.kerf");
  const std::string command = "trap \"\" XFSZ; ulimit -f 4; " + std::string(KERF_CLI) + " -q export " +
                              (dir / "demo.kerf").string() + " --face A --px-per-mm 8 --out " +
                              (dir / "A.tif").string() + " 2>&1";
  FILE* pipe = ::popen(("bash -c '" + command + "'").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) output.append(buffer, n);
  const int status = ::pclose(pipe);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2) << output;
  EXPECT_NE(output.find("kerf-cli: error: cannot write " + (dir / "A.tif").string()), std::string::npos)
      << output;
  EXPECT_FALSE(fs::exists(dir / "A.tif"));
  EXPECT_EQ(filesIn(dir), 1u) << "a temporary file was left";
}

TEST(OutputFailures, TemporaryLeftByAKilledWriterIsRemovedByTheNextWrite) {
  // A writer killed mid-write leaves its hidden temporary; the next write into the same folder, of any
  // file, removes every temporary whose process is gone (a pid above Linux's pid_max never exists), and
  // leaves a live writer's and names that only look alike (issue 21).
  const fs::path dir = folder("killed_writer");
  const fs::path dead = dir / ".block.tmp999999999-0.kerf",
                 live = dir / (".block.tmp" + std::to_string(::getppid()) + "-3.kerf");
  const fs::path other = dir / ".other.tmp999999999-0.kerf", noExtension = dir / ".log.tmp999999999-12";
  const fs::path staging = dir / ".detect.tmp999999999-1";  // a killed detect's staging folder
  const fs::path notOurs = dir / ".block.tmpnotes.kerf", visible = dir / "block.tmp999999999-0.kerf",
                 trailing = dir / ".block.tmp999999999-0x";
  for (const fs::path& p : {dead, live, other, noExtension, notOurs, visible, trailing})
    writeText(p, "partial");
  fs::create_directories(staging);
  writeText(staging / "A_arl.png", "partial");
  writeTextAtomically(dir / "block.kerf", "{}");
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_FALSE(fs::exists(other));  // another target's, in the same folder
  EXPECT_FALSE(fs::exists(noExtension));
  EXPECT_FALSE(fs::exists(staging));
  EXPECT_TRUE(fs::exists(notOurs));
  EXPECT_TRUE(fs::exists(visible));
  EXPECT_TRUE(fs::exists(trailing));
  EXPECT_EQ(readBytes(dir / "block.kerf"), "{}");
}

TEST(OutputFailures, KilledVolumeExportsTemporaryIsRemovedByTheNextExportIntoTheFolder) {
  // The example: a kill during export-volume left a 50 MB hidden temporary until the next write
  // of that same file. Simulated with a sparse 50 MB file of a process that does not exist; exporting
  // a face image into the same folder removes it.
  const fs::path dir = folder("killed_volume_export");
  saveProject(Project(), dir / "block.kerf");
  const fs::path stale = dir / ".growth.tmp999999999-0.nrrd";
  writeText(stale, "NRRD0004\n");
  fs::resize_file(stale, 50u << 20);
  const CliResult r = runCli("export " + (dir / "block.kerf").string() + " --face A --px-per-mm 1 --out " +
                             (dir / "A.png").string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(dir / "A.png"));
}

TEST(OutputFailures, ReadOnlyFolder) {
  // As root (CI, containers) permissions do not apply, so kerf-cli runs as "nobody" through setpriv.
  const bool root = ::geteuid() == 0;
  if (root && std::system("command -v setpriv >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "running as root without setpriv (util-linux): a read-only folder cannot be shown";
  const fs::path dir = folder("read_only");
  saveProject(Project(), dir / "block.kerf");
  fs::create_directories(dir / "locked");
  fs::permissions(dir / "locked", fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                                      fs::perms::group_exec | fs::perms::others_read |
                                      fs::perms::others_exec);
  fs::permissions(dir, fs::perms::all);  // nobody may read the project
  fs::permissions(dir / "block.kerf",
                  fs::perms::owner_read | fs::perms::owner_write | fs::perms::others_read);
  const std::string runAs = root ? "setpriv --reuid=65534 --regid=65534 --clear-groups " : "";
  const std::string project = (dir / "block.kerf").string(), locked = (dir / "locked").string();
  const struct {
    std::string arguments, message;
  } cases[] = {
      {"export " + project + " --face A --out " + locked + "/A.png",
       "cannot write " + locked + "/A.png: folder " + locked + " is not writable (Permission denied)"},
      {"export " + project + " --res 8 --out " + locked + "/growth.nrrd",
       "cannot write " + locked + "/growth.nrrd: folder " + locked + " is not writable"},
      {"export " + project + " --res 8 --out " + locked + "/growth.vdb",
       "cannot write " + locked + "/growth.vdb: folder " + locked + " is not writable"},
      {"render-faces " + project + " --px-per-mm 1 --out " + locked + "/faces",
       "cannot create the folder " + locked + "/faces: Permission denied"},
      {"export " + project + " --depth-stack A,1,2 --px-per-mm 1 --out " + locked + "/stack",
       "cannot create the folder " + locked + "/stack: Permission denied"},
  };
  for (const auto& c : cases) {
    const CliResult r = runCli(c.arguments, runAs);
    EXPECT_EQ(r.exitCode, 2) << c.arguments << "\n" << r.output;
    EXPECT_NE(r.output.find("kerf-cli: error: " + c.message), std::string::npos) << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir / "locked"));
  fs::permissions(dir / "locked", fs::perms::owner_all);
}
