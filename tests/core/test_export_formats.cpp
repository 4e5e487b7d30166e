// The export-format table (core/export/export_formats.hpp, issue 15 item 4): every extension it lists is
// found again, the kinds' sentences are built from it, and a writer refuses a format of another kind by
// the table's words.
#include <gtest/gtest.h>

#include <cctype>
#include <set>

#include "export/export_formats.hpp"
#include "export/export_job.hpp"
#include "export/volume_writer.hpp"
#include "util/error.hpp"

namespace kerf {
namespace {

TEST(ExportFormats, EveryExtensionNamesItsFormatInAnyCase) {
  std::set<std::string_view> seen;
  for (const ExportFormatInfo& info : exportFormats()) {
    EXPECT_EQ(exportFormatInfo(info.format).name, info.name);
    for (std::string_view e : info.extensions) {
      if (e.empty()) continue;
      EXPECT_TRUE(seen.insert(e).second) << e << " is listed twice";
      std::string upper = "PART" + std::string(e);
      for (char& c : upper) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      for (const std::string& name : {"part" + std::string(e), upper}) {
        const auto found = exportFormatOf(name);
        ASSERT_TRUE(found) << name;
        EXPECT_EQ(found->format, info.format) << name;
      }
    }
  }
  EXPECT_FALSE(exportFormatOf("folder"));
  EXPECT_FALSE(exportFormatOf("x.xyz"));
}

TEST(ExportFormats, TheKindsSentencesComeFromTheTable) {
  EXPECT_EQ(extensionList(ExportKind::Image), ".png, .tif, .tiff or .exr");
  EXPECT_EQ(extensionList(ExportKind::Volume), ".nrrd or .vdb");
  EXPECT_EQ(extensionWords(ExportKind::Part), ".obj .glb");
  EXPECT_EQ(extensionList(ExportKind::DepthStack), "");
  EXPECT_EQ(fileFilter(exportFormatInfo(ExportFormat::Tiff)), "TIFF (*.tif *.tiff)");
}

TEST(ExportFormats, ExportKindOfAgreesWithTheTableForEveryFormat) {
  for (const ExportFormatInfo& info : exportFormats()) {
    ExportRequest request;
    request.out = "out" + std::string(info.extensions[0]);
    if (info.kind == ExportKind::Image) request.face = FaceId::A;
    EXPECT_EQ(exportKindOf(request), info.kind) << request.out;
  }
}

TEST(ExportFormats, AWriterRefusesAnotherKindsFormatNamingTheFileAndItsOwnFormats) {
  try {
    openVolumeWriter("grain.png", NrrdLayout{});
    FAIL() << "a volume writer opened a .png";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("grain.png"), std::string::npos) << message;
    EXPECT_NE(message.find("use .nrrd or .vdb"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace kerf
