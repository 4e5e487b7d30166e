// CPU/GPU parity of the knot model: the GLSL twin (shaders/knots.glsl, gpu/gpu_board_renderer.*)
// against core's renderBoardFace, on the three golden boards of tests/core/test_knot_render.cpp (boards
// cut from the CT-measured spruce log), on a random log with a rotated board, and without culling.
#include <QGuiApplication>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include "../core/spruce_log.hpp"
#include "gl_renderer_fixture.hpp"
#include "gpu/gpu_board_renderer.hpp"
#include "image/image_difference.hpp"
#include "io/image.hpp"
#include "io/log_data_import.hpp"

using namespace kerf;
using kerf::testing::earlyDeadKnot;
namespace fs = std::filesystem;

namespace {

// Both sides compute in 32-bit floats, in the same order, from the same tables (the knot noise is core's
// own table), so they differ only where llvmpipe's sqrt/atan/sin/cos/pow/exp differ from libm by an ulp or
// so. Measured on Mesa llvmpipe (docs/knots.md): mean |difference| 5e-7 .. 3.6e-6, max 0.0014, no channel
// over 0.01. The limits leave room for another GPU's transcendentals and for a few pixels where the dead
// knot outline (a yes/no threshold) or a window edge flips.
constexpr double kMaxMeanAbs = 5e-5;
constexpr float kPixelTolerance = 0.01f;
constexpr double kMaxShareOver = 5e-4;

double maxAbsDifference(const Image& a, const Image& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.pixels.size(); ++i)
    m = std::max(m, std::abs(double(a.pixels[i]) - b.pixels[i]));
  return m;
}

}  // namespace

class KnotParityTest : public QObject, kerf::testing::GlRendererFixture<GpuBoardRenderer> {
  Q_OBJECT

 private slots:
  void initTestCase() {
    const std::string error = startRenderer();
    QVERIFY2(error.empty(), error.c_str());
  }

  void cleanupTestCase() { stopRenderer(); }

  void flatSawnBoardThroughKnots() {
    if (!gran()) QSKIP("the spruce log (shared/data) is absent");
    compareBoard(*gran(), gran()->colorMap, defaultBoard(*gran()), 320, "knots_flat_sawn");
  }

  // All 108 knots uploaded (no culling): the knot tables and the noise texture span several rows.
  void unculledSpruceBoard() {
    if (!gran()) QSKIP("the spruce log (shared/data) is absent");
    const KnotField field(*gran(), KnotSettings{});
    BoardRenderOptions culled, all;
    culled.resolution = all.resolution = 160;
    all.cull = false;
    BoardRenderStats stats;
    const Image cpu = renderBoardFace(field, gran()->colorMap, defaultBoard(*gran()), culled);
    const Image gpu = renderer_->render(field, gran()->colorMap, defaultBoard(*gran()), all, &stats);
    QCOMPARE(stats.boardKnots, 108);
    const ImageDifference d = compareImages(cpu, gpu, kPixelTolerance);
    qInfo() << "unculled spruce board: mean abs" << d.meanAbs << "max abs" << maxAbsDifference(cpu, gpu);
    QVERIFY(d.meanAbs < kMaxMeanAbs);
    QVERIFY(d.shareOverTolerance < kMaxShareOver);
  }

  void boardAlongKnotAxis() {
    if (!gran()) QSKIP("the spruce log (shared/data) is absent");
    compareBoard(*gran(), gran()->colorMap, boardAlongKnot(*gran(), 40, {130.0f, 130.0f, 30.0f}), 320,
                 "knots_along_axis");
  }

  void deadKnotWithButterfly() {
    if (!gran()) QSKIP("the spruce log (shared/data) is absent");
    const int knot = earlyDeadKnot(*gran());
    QVERIFY(knot >= 0);
    const float distance = gran()->knots[knot].deathDistance + 25.0f;
    const BoardRenderStats stats = compareBoard(
        *gran(), gran()->colorMap, boardAcrossKnot(*gran(), knot, distance, {80.0f, 80.0f, 20.0f}), 320,
        "knots_dead_butterfly");
    QVERIFY2(stats.meanKnotsInReach > 0.1, "the dead knot board should have knots in reach");
  }

  // A random log (colour map from the parameters), a rotated board, another face, non-default settings,
  // and the unculled path: the culling lists must not change the GPU's picture either.
  void randomLogRotatedBoard() {
    const LogModel log = generateRandomLog({.seed = 5});
    const WoodColorMap colors = woodColorMapFromParameters(WoodParameters{}, log.stem.maxRadius());
    Board board = defaultBoard(log);
    board.rotationDeg = {12.0f, 20.0f, 7.0f};
    KnotSettings settings;
    settings.knotButterfly = 0.9f, settings.knotDeadInversion = -0.8f, settings.knotOutlineWidth = 0.02f;
    compareBoard(log, colors, board, 200, "knots_random_rotated", settings, FaceId::C);
    const KnotField field(log, settings);
    BoardRenderOptions culled, all;
    culled.resolution = all.resolution = 160;
    all.cull = false;
    const Image a = renderer_->render(field, colors, board, culled);
    const Image b = renderer_->render(field, colors, board, all);
    QCOMPARE(maxAbsDifference(a, b), 0.0);
  }

  // Knot checks (knots.checks, Kerf's own: core/model/kernels/knot_checks.glsl) close up: a 24 mm board
  // across a dead knot of a random log, 25 mm past its death, at 25 px/mm with strong checks. The cracks
  // are in the CPU's picture (darker pixels than without checks) and the GPU draws the same.
  void deadKnotChecksCloseUp() {
    const LogModel log = generateRandomLog({.seed = 3});
    int knot = -1;
    for (int k = 0; k < static_cast<int>(log.knots.size()) && knot < 0; ++k) {
      const Knot& candidate = log.knots[k];  // dies 20-60 mm from the pith, away from the log's ends
      if (candidate.deathDistance > 20.0f && candidate.deathDistance < 60.0f &&
          candidate.heights[0] > 300.0f && candidate.heights[0] < 1100.0f)
        knot = k;
    }
    QVERIFY(knot >= 0);
    const WoodColorMap colors = woodColorMapFromParameters(WoodParameters{}, log.stem.maxRadius());
    const Board board =
        boardAcrossKnot(log, knot, log.knots[knot].deathDistance + 25.0f, {24.0f, 24.0f, 10.0f});
    KnotSettings settings, none;
    settings.knotChecks = 2.0f;
    none.knotChecks = 0.0f;
    BoardRenderOptions options;
    options.resolution = 600;
    const Image plain = renderBoardFace(KnotField(log, none), colors, board, options);
    const Image cpu = renderBoardFace(KnotField(log, settings), colors, board, options);
    int cracked = 0;
    for (std::size_t i = 0; i + 2 < cpu.pixels.size(); i += static_cast<std::size_t>(cpu.channels))
      cracked += cpu.pixels[i] + cpu.pixels[i + 1] + cpu.pixels[i + 2] <
                 0.8f * (plain.pixels[i] + plain.pixels[i + 1] + plain.pixels[i + 2]);
    qInfo() << "knot" << knot << "checks: cracked pixels" << cracked;
    QVERIFY2(cracked > 50, qPrintable(QString("%1 cracked pixels").arg(cracked)));
    compareBoard(log, colors, board, 600, "knots_checks_close_up", settings);
  }

 private:
  static const LogModel* gran() { return kerf::testing::granLog(); }

  BoardRenderStats compareBoard(const LogModel& log, const WoodColorMap& colors, const Board& board,
                                int resolution, const QString& name, const KnotSettings& settings = {},
                                FaceId face = FaceId::A) {
    const KnotField field(log, settings);
    BoardRenderOptions options;
    options.resolution = resolution;
    options.face = face;
    BoardRenderStats cpuStats, gpuStats;
    const Image cpu = renderBoardFace(field, colors, board, options, &cpuStats);
    const Image gpu = renderer_->render(field, colors, board, options, &gpuStats);
    [&] {
      QCOMPARE(gpu.width, cpu.width);
      QCOMPARE(gpu.height, cpu.height);
      QCOMPARE(gpu.channels, cpu.channels);
      QCOMPARE(gpuStats.boardKnots, cpuStats.boardKnots);
      QCOMPARE(gpuStats.meanTileKnots, cpuStats.meanTileKnots);
      // The count of knots in reach per pixel decides which knots take part: it must match almost exactly.
      QVERIFY2(std::abs(gpuStats.meanKnotsInReach - cpuStats.meanKnotsInReach) < 1e-3,
               qPrintable(QString("knots in reach: cpu %1 gpu %2")
                              .arg(cpuStats.meanKnotsInReach)
                              .arg(gpuStats.meanKnotsInReach)));
      const QString dir = QStringLiteral(KERF_TEST_ARTIFACTS);
      writeImage((dir + "/parity_" + name + "_cpu.png").toStdString(), cpu);
      writeImage((dir + "/parity_" + name + "_gpu.png").toStdString(), gpu);
      const ImageDifference d = compareImages(cpu, gpu, kPixelTolerance);
      qInfo().noquote() << name << "board knots" << cpuStats.boardKnots << "in reach/pixel"
                        << cpuStats.meanKnotsInReach << "mean abs" << d.meanAbs << "max abs"
                        << maxAbsDifference(cpu, gpu) << "share over" << kPixelTolerance
                        << d.shareOverTolerance;
      QVERIFY2(d.meanAbs < kMaxMeanAbs, qPrintable(name + " mean difference too large"));
      QVERIFY2(d.shareOverTolerance < kMaxShareOver, qPrintable(name + " too many differing pixels"));
    }();
    return cpuStats;
  }
};

QTEST_MAIN(KnotParityTest)
#include "test_knot_parity.moc"
