// CPU/GPU parity of the board's wood in log mode: the cut panel's GLSL path (image_plane.frag with
// shaders/board_wood.glsl, knots culled per cell of the board's 3D grid, GpuImageRenderer::renderBoardCut)
// against core's renderBoardCut, on slanted cuts through boards of seeded random logs and, where
// shared/data has it, of the CT-measured spruce log.
#include <QGuiApplication>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QtTest>
#include <algorithm>
#include <cmath>

#include "../core/spruce_log.hpp"
#include "gl_renderer_fixture.hpp"
#include "gpu/gpu_image_renderer.hpp"
#include "io/image.hpp"
#include "io/log_data_import.hpp"

using namespace kerf;

namespace {

// As in test_knot_parity: the same float operations from the same tables; what differs is llvmpipe's
// transcendentals against libm and, here, the pixel's board point (origin + steps on the GPU, the plane's
// own mapping on the CPU, a few ulps apart). A dead knot's outline or a ring on a steep slope may flip a
// pixel; the limits leave room for that and for another GPU.
constexpr double kMaxMeanAbs = 5e-4;
constexpr float kPixelTolerance = 0.02f;
constexpr double kMaxShareOver = 2e-3;

struct Comparison {
  double meanAbs = 0, maxAbs = 0, shareOver = 0;
  int wood = 0;          // pixels on the board on both sides
  int coverageDiff = 0;  // pixels on the board on one side only
};

Comparison compareCuts(const Image& cpu, const Image& gpu) {
  Comparison c;
  long over = 0, channels = 0;
  for (int y = 0; y < cpu.height; ++y)
    for (int x = 0; x < cpu.width; ++x) {
      const float* a = cpu.pixel(x, y);
      const float* b = gpu.pixel(x, y);
      if ((a[3] > 0.5f) != (b[3] > 0.5f)) {
        ++c.coverageDiff;
        continue;
      }
      if (a[3] <= 0.5f) continue;
      ++c.wood;
      for (int k = 0; k < 3; ++k) {
        const double d = std::abs(double(a[k]) - b[k]);
        c.meanAbs += d;
        c.maxAbs = std::max(c.maxAbs, d);
        over += d > kPixelTolerance;
        ++channels;
      }
    }
  c.meanAbs /= std::max<long>(channels, 1);
  c.shareOver = static_cast<double>(over) / std::max<long>(channels, 1);
  return c;
}

// A cut through the board's centre, tilted out of every principal plane.
CutPlane slantedCut(float azimuthDeg, float elevationDeg, float offsetMm) {
  CutPlaneSetting s;
  s.azimuthDeg = azimuthDeg;
  s.elevationDeg = elevationDeg;
  s.offsetMm = offsetMm;
  return s.plane();
}

}  // namespace

class BoardCutParityTest : public QObject, kerf::testing::GlRendererFixture<GpuImageRenderer> {
  Q_OBJECT

 private slots:
  void initTestCase() {
    const std::string error = startRenderer();
    QVERIFY2(error.empty(), error.c_str());
  }

  void cleanupTestCase() { stopRenderer(); }

  void randomLogDefaultBoard() {
    const LogModel log = generateRandomLog({.seed = 3});
    compare(log, woodColorMapFromParameters(WoodParameters{}, log.stem.maxRadius()), defaultBoard(log),
            slantedCut(35.0f, 25.0f, 4.0f), "board_cut_random3");
  }

  // A rotated board, a steeper cut, non-default knot settings.
  void randomLogRotatedBoard() {
    const LogModel log = generateRandomLog({.seed = 5});
    Board board = defaultBoard(log);
    board.rotationDeg = {12.0f, 20.0f, 7.0f};
    KnotSettings settings;
    settings.knotButterfly = 0.9f, settings.knotDeadInversion = -0.8f, settings.knotOutlineWidth = 0.02f;
    compare(log, woodColorMapFromParameters(WoodParameters{}, log.stem.maxRadius()), board,
            slantedCut(-60.0f, 50.0f, -3.0f), "board_cut_random5_rotated", settings);
  }

  void spruceLogDefaultBoard() {
    const LogModel* gran = kerf::testing::granLog();
    if (!gran) QSKIP("the spruce log (shared/data/logs/spruce-gran1) is absent");
    compare(*gran, gran->colorMap, defaultBoard(*gran), slantedCut(20.0f, 30.0f, 5.0f), "board_cut_spruce");
  }

 private:
  void compare(const LogModel& log, const WoodColorMap& colors, const Board& board, const CutPlane& plane,
               const QString& name, const KnotSettings& settings = {}) {
    const BoardWood wood{std::make_shared<const KnotField>(log, settings),
                         std::make_shared<const WoodColorMap>(colors), board};
    constexpr float kPxPerMm = 3.0f;
    const Image cpu = renderBoardCut(wood, plane, kPxPerMm);
    const Image gpu = renderer_->renderBoardCut(wood, plane, kPxPerMm);
    // The table uploads leave the unpack alignment as they found it (the default): QPainter's glyph
    // uploads rely on it, and the cut panel's rulers came out garbled when it stayed at 1.
    GLint alignment = 0;
    QOpenGLContext::currentContext()->functions()->glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    QCOMPARE(alignment, 4);
    QCOMPARE(gpu.width, cpu.width);
    QCOMPARE(gpu.height, cpu.height);
    const QString dir = QStringLiteral(KERF_TEST_ARTIFACTS);
    writeImage((dir + "/parity_" + name + "_cpu.png").toStdString(), cpu);
    writeImage((dir + "/parity_" + name + "_gpu.png").toStdString(), gpu);
    const Comparison c = compareCuts(cpu, gpu);
    const KnotCellGrid grid = buildKnotCellGrid(*wood.field, board, knotGridCells(board.size));
    qInfo().noquote() << name << cpu.width << "x" << cpu.height << "board knots" << grid.boardKnots
                      << "knots per cell" << grid.meanKnotsPerCell() << "mean abs" << c.meanAbs << "max abs"
                      << c.maxAbs << "share over" << kPixelTolerance << c.shareOver << "coverage differs"
                      << c.coverageDiff;
    QVERIFY2(c.wood > cpu.width * cpu.height / 3, "the cut should cover much of its bounding rectangle");
    QVERIFY2(grid.boardKnots > 0, "the board should have knots in reach");
    // Only pixels whose centre lies on the board's edge may be in on one side and out on the other.
    QVERIFY2(c.coverageDiff <= 2 * (cpu.width + cpu.height), qPrintable(name + ": coverage differs"));
    QVERIFY2(c.meanAbs < kMaxMeanAbs, qPrintable(name + ": mean difference too large"));
    QVERIFY2(c.shareOver < kMaxShareOver, qPrintable(name + ": too many differing pixels"));
  }
};

QTEST_MAIN(BoardCutParityTest)
#include "test_board_cut_parity.moc"
