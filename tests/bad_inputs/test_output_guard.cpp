// The output guard (io/output_guard.hpp, app/cli/output_options.*; issue 21): outputs that are inputs or
// other outputs of the same command, FIFOs and device nodes, symbolic links, read-only files and the
// permission bits of a replaced file; and detect's outputs, moved into place only when all are written.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <string>

#include "bad_input_files.hpp"
#include "io/atomic_file.hpp"
#include "io/image.hpp"
#include "io/output_guard.hpp"
#include "io/project.hpp"
#include "run_cli.hpp"

namespace kerf::bad {
namespace {

class OutputGuard : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = freshTestFolder("output_guard"); }
  // kerf-cli exits with code 2 naming the problem, and the folder holds what it held before, byte for
  // byte, and no temporary.
  void expectRefusedLeavingTheFolder(const std::string& arguments, const std::string& problem) {
    std::map<std::string, std::string> before;
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.is_regular_file()) before[entry.path().filename().string()] = readBytes(entry.path());
    const CliResult r = runCli(arguments);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_TRUE(std::regex_search(r.output, std::regex(problem))) << r.output;
    std::map<std::string, std::string> after;
    for (const auto& entry : fs::directory_iterator(dir_))
      if (entry.is_regular_file()) after[entry.path().filename().string()] = readBytes(entry.path());
    EXPECT_EQ(before, after) << "a file was written, changed or left";
  }
  fs::path dir_;
};

// A closed tetrahedron, mm.
void writeMesh(const fs::path& path) {
  writeText(path, "v 0 0 0\nv 10 0 0\nv 0 10 0\nv 0 0 10\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
}

TEST_F(OutputGuard, MeshAsItsOwnOutputIsRefused) {
  saveProject(Project(), dir_ / "block.kerf");
  writeMesh(dir_ / "m.obj");
  expectRefusedLeavingTheFolder("export " + (dir_ / "block.kerf").string() + " --mesh " +
                                    (dir_ / "m.obj").string() + " --out " + (dir_ / "m.obj").string(),
                                "--out .*m.obj is also the input --mesh");
}

TEST_F(OutputGuard, PhotoAsItsOwnOutputIsRefused) {
  writePhoto(dir_ / "p.png", 16, 16);
  expectRefusedLeavingTheFolder("rectify " + (dir_ / "p.png").string() +
                                    " --corners 0,0,15,0,15,15,0,15 --size-mm 10,10 --out " +
                                    (dir_ / "p.png").string(),
                                "--out .*p.png is also the input PHOTO");
  // Through another name of the same file (a hard link).
  fs::create_hard_link(dir_ / "p.png", dir_ / "q.png");
  expectRefusedLeavingTheFolder("rectify " + (dir_ / "p.png").string() +
                                    " --corners 0,0,15,0,15,15,0,15 --size-mm 10,10 --out " +
                                    (dir_ / "q.png").string(),
                                "is also the input PHOTO");
}

TEST_F(OutputGuard, TwoOutputsWithOneNameAreRefused) {
  expectRefusedLeavingTheFolder("render-board random:1 --res 16 --out " + (dir_ / "x.png").string() +
                                    " --save-log " + (dir_ / "x.png").string(),
                                "--out and --save-log name the same file");
}

TEST_F(OutputGuard, InputsReadInsideAFolderAreCaughtWhenWritten) {
  // What the command-line check cannot see (a sample folder's photos): the guard refuses at the write.
  writePhoto(dir_ / "p.png", 8, 8);
  const std::string before = readBytes(dir_ / "p.png");
  refuseOutputsOverInputs(true);
  const Image photo = readImage(dir_ / "p.png");
  const std::string error = errorOf([&] { writeImage(dir_ / "p.png", photo); });
  refuseOutputsOverInputs(false);
  EXPECT_NE(error.find("p.png: it is also an input of this command"), std::string::npos) << error;
  EXPECT_EQ(readBytes(dir_ / "p.png"), before);
}

TEST_F(OutputGuard, FifoAndDeviceNodesAreNeverReplaced) {
  const fs::path fifo = dir_ / "pipe.png";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expectRefusedLeavingTheFolder("render-board random:1 --res 16 --out " + fifo.string(),
                                "pipe.png: it is a pipe \\(FIFO\\); Kerf writes only regular files");
  EXPECT_TRUE(fs::is_fifo(fifo));
  // A device node like /dev/null (made here, so that a failure could only replace this copy).
  const fs::path null = dir_ / "null.kerf";
  if (::mknod(null.c_str(), S_IFCHR | 0666, makedev(1, 3)) != 0) GTEST_SKIP() << "mknod needs root";
  EXPECT_NE(errorOf([&] { saveProject(Project(), null); }).find("null.kerf: it is a character device"),
            std::string::npos);
  EXPECT_TRUE(fs::is_character_file(null));
  // And through a symbolic link to it.
  fs::create_symlink(null, dir_ / "link.kerf");
  EXPECT_NE(errorOf([&] { saveProject(Project(), dir_ / "link.kerf"); }).find("a character device"),
            std::string::npos);
  EXPECT_TRUE(fs::is_character_file(null));
}

TEST_F(OutputGuard, SymbolicLinkIsWrittenThroughAndKept) {
  fs::create_directories(dir_ / "real");
  Project project;
  saveProject(project, dir_ / "real" / "block.kerf");
  fs::create_symlink(fs::path("real") / "block.kerf", dir_ / "link.kerf");
  project.params = loadProject(dir_ / "real" / "block.kerf").params;
  project.block = Block(glm::vec3(30.0f));
  saveProject(project, dir_ / "link.kerf");
  EXPECT_TRUE(fs::is_symlink(dir_ / "link.kerf")) << "the link was replaced by a file";
  EXPECT_FLOAT_EQ(loadProject(dir_ / "real" / "block.kerf").block.size().x, 30.0f);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "real"), fs::directory_iterator()), 1)
      << "a temporary was left";
}

TEST_F(OutputGuard, ReadOnlyFileIsRefusedAndModeIsKept) {
  const fs::path file = dir_ / "block.kerf";
  saveProject(Project(), file);
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write);  // 0600
  saveProject(Project(), file);
  EXPECT_EQ(fs::status(file).permissions() & fs::perms::mask, fs::perms::owner_read | fs::perms::owner_write)
      << "re-saving changed the file's mode";
  fs::permissions(file, fs::perms::owner_read | fs::perms::group_read);  // 0440: read-only
  const std::string before = readBytes(file);
  Project other;
  other.block = Block(glm::vec3(20.0f));
  const std::string error = errorOf([&] { saveProject(other, file); });
  EXPECT_NE(error.find("block.kerf: the file is read-only"), std::string::npos) << error;
  EXPECT_EQ(readBytes(file), before);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 1)
      << "a temporary was left";
}

TEST_F(OutputGuard, DetectOnAFullDiskLeavesNoPartialRingImages) {
  // Six faces' X_arl.png and contours.json: with a 2 KiB file-size limit (as a full disk), some images fit
  // and contours.json does not. Before, the images written so far stayed in --out for a later fit.
  const fs::path sample = dir_ / "sample";
  fs::create_directories(sample);
  for (const char* face : {"A", "B", "C", "D", "E", "F"})
    writePhoto(sample / (std::string(face) + "_col.png"), 64, 64);
  const fs::path out = dir_ / "rings";
  const std::string command = "trap \"\" XFSZ; ulimit -f 2; " + std::string(KERF_CLI) + " -q detect " +
                              sample.string() + " --out " + out.string();
  const CliResult r = runShell(command);
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("cannot write"), std::string::npos) << r.output;
  ASSERT_TRUE(fs::is_directory(out));
  EXPECT_TRUE(fs::is_empty(out)) << "detect left files: " << fs::directory_iterator(out)->path();
}

}  // namespace
}  // namespace kerf::bad
