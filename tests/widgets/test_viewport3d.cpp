// The live 3D view: OrbitCamera and CutGizmo maths, and Viewport3D on the demo block under a real
// OpenGL context (Mesa under xvfb-run): the picture, the cut, dragging the cut plane, snapping, the
// reduced-resolution frames while interacting, the face photos, and frame times (printed).
#include <QApplication>
#include <QElapsedTimer>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalSpy>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <memory>
#include <vector>

#include "../core/spruce_log.hpp"
#include "cut_gizmo.hpp"
#include "demo/demo_block.hpp"
#include "orbit_camera.hpp"
#include "qt_image.hpp"
#include "render/board_wood.hpp"
#include "render/renderers.hpp"
#include "viewport3d.hpp"

using namespace kerf;

namespace {

QString artifact(const QString& name) {
  return QStringLiteral(KERF_TEST_ARTIFACTS) + "/viewport3d_" + name + ".png";
}

glm::vec3 rgbAt(const QImage& image, int x, int y) {
  const QColor c = image.pixelColor(x, y);
  return {static_cast<float>(c.redF()), static_cast<float>(c.greenF()), static_cast<float>(c.blueF())};
}

// Mean absolute difference of two same-sized images, per channel, 0..1.
double meanDifference(const QImage& a, const QImage& b) {
  const QImage x = a.convertToFormat(QImage::Format_RGB888), y = b.convertToFormat(QImage::Format_RGB888);
  if (x.size() != y.size()) return 1.0;
  double sum = 0.0;
  for (int row = 0; row < x.height(); ++row) {
    const uchar* p = x.constScanLine(row);
    const uchar* q = y.constScanLine(row);
    for (int i = 0; i < x.width() * 3; ++i) sum += std::abs(int(p[i]) - int(q[i]));
  }
  return sum / (255.0 * x.width() * x.height() * 3);
}

// A wood colour: warm (red over green over blue), neither grey nor black.
bool looksLikeWood(glm::vec3 c) {
  return c.x > c.y && c.y > c.z && c.x - c.z > 0.12f && c.x > 0.2f;
}

bool looksLikeBackground(glm::vec3 c) {
  return std::abs(c.x - c.y) < 0.04f && std::abs(c.y - c.z) < 0.05f && c.x > 0.1f && c.x < 0.45f;
}

QPoint toQPoint(glm::vec3 projected) {
  return {static_cast<int>(std::lround(projected.x)), static_cast<int>(std::lround(projected.y))};
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

class Viewport3DTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    project_ = demoProject();
    model_ = std::make_shared<const WoodModel>(project_);
    view_ = std::make_unique<Viewport3D>();
    view_->resize(900, 640);
    view_->setModel(model_);
    view_->setReducedResolutionDivisor(1);  // deterministic pictures; the speed test turns it back on
    view_->show();
    QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
    const QImage first = view_->grabFramebuffer();
    QVERIFY2(!view_->rendererName().isEmpty(), "no OpenGL context (run under xvfb-run with Mesa)");
    qInfo().noquote() << "GL_RENDERER:" << view_->rendererName();
    QVERIFY(!first.isNull());
    QVERIFY2(view_->ready(), "the 3D view's shaders did not build");
  }

  void cleanupTestCase() { view_.reset(); }

  // Every test starts from a refined picture (a drag in the previous test leaves the view interactive
  // for the refine delay).
  void init() {
    if (view_) view_->refineNow();
  }

  // --- OrbitCamera ---------------------------------------------------------------------------------

  void cameraCentreRayHitsTarget() {
    OrbitCamera camera;
    camera.setViewportSize({800, 500});
    camera.setScene({0, 0, 0}, 35);
    camera.setTarget({3, -2, 5});
    camera.setAngles(40, 20);
    camera.setDistance(150);
    const Ray ray = camera.rayThrough({400, 250});
    const glm::vec3 toTarget = camera.target() - ray.origin;
    QVERIFY(glm::length(glm::cross(ray.direction, toTarget)) < 1e-3f * glm::length(toTarget));
    QVERIFY(glm::dot(ray.direction, toTarget) > 0);
    QVERIFY(std::abs(glm::length(camera.eye() - camera.target()) - 150.0f) < 1e-3f);
    const glm::vec3 p = camera.project(camera.target());
    QVERIFY(std::abs(p.x - 400) < 1e-3f && std::abs(p.y - 250) < 1e-3f);
    QVERIFY(std::abs(p.z - 150) < 1e-2f);
  }

  void cameraProjectAndRayAgree() {
    OrbitCamera camera;
    camera.setViewportSize({640, 480});
    camera.setAngles(-70, 35);
    camera.setDistance(120);
    for (glm::vec3 q : {glm::vec3(10, 5, -3), glm::vec3(-20, 20, 20), glm::vec3(0, -15, 8)}) {
      const glm::vec3 px = camera.project(q);
      const Ray ray = camera.rayThrough({px.x, px.y});
      const glm::vec3 d = q - ray.origin;
      QVERIFY2(glm::length(glm::cross(ray.direction, d)) < 1e-3f * glm::length(d), "ray misses the point");
    }
    // The view-projection matrix agrees with project().
    const glm::vec3 q(7, -4, 11);
    const glm::vec4 clip = camera.viewProjection() * glm::vec4(q, 1);
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const glm::vec3 px = camera.project(q);
    QVERIFY(std::abs((ndc.x + 1) * 320 - px.x) < 0.05f);
    QVERIFY(std::abs((1 - ndc.y) * 240 - px.y) < 0.05f);
    QVERIFY(std::abs(clip.z / clip.w) < 1.0f);  // between the near and far planes
  }

  void cameraOrientations() {
    OrbitCamera camera;
    camera.setView(OrbitCamera::View::Front);  // looking at face A along -z, y up
    QVERIFY(glm::length(camera.forward() - glm::vec3(0, 0, -1)) < 1e-5f);
    QVERIFY(glm::length(camera.up() - glm::vec3(0, 1, 0)) < 1e-5f);
    camera.setView(OrbitCamera::View::Right);  // looking at face E along -x
    QVERIFY(glm::length(camera.forward() - glm::vec3(-1, 0, 0)) < 1e-5f);
    camera.setView(OrbitCamera::View::Top);  // straight down onto face B, upright as its image (up -z)
    QVERIFY(glm::length(camera.forward() - glm::vec3(0, -1, 0)) < 1e-5f);
    QVERIFY(glm::length(camera.up() - glm::vec3(0, 0, -1)) < 1e-5f);
    QVERIFY(glm::length(camera.right() - glm::vec3(1, 0, 0)) < 1e-5f);
    camera.orbit({0, 1000});  // pitch stays clamped
    QCOMPARE(camera.pitchDeg(), 90.0f);
    camera.setAngles(190, 0);
    QVERIFY(std::abs(camera.yawDeg() + 170.0f) < 1e-3f);
  }

  void cameraZoomKeepsCursorPoint() {
    OrbitCamera camera;
    camera.setViewportSize({800, 600});
    camera.fit(glm::vec3(20));
    const glm::vec2 cursor(620, 140);
    const Ray before = camera.rayThrough(cursor);
    const glm::vec3 anchor = before.at(camera.distance() / glm::dot(before.direction, camera.forward()));
    const float distance = camera.distance();
    camera.zoom(2, cursor);
    QVERIFY(camera.distance() < distance);
    const glm::vec3 px = camera.project(anchor);
    QVERIFY2(std::abs(px.x - cursor.x) < 0.05f && std::abs(px.y - cursor.y) < 0.05f,
             "the point under the cursor moved while zooming");
    // Pan: the target-depth point under the cursor follows the mouse.
    const glm::vec3 onTargetPlane = camera.target() + 5.0f * camera.right();
    const glm::vec3 p0 = camera.project(onTargetPlane);
    camera.pan({30, -12});
    const glm::vec3 p1 = camera.project(onTargetPlane);
    QVERIFY(std::abs(p1.x - p0.x - 30) < 0.05f && std::abs(p1.y - p0.y + 12) < 0.05f);
  }

  void cameraFitShowsWholeBlock() {
    for (glm::vec2 size : {glm::vec2(800, 600), glm::vec2(300, 900)}) {
      OrbitCamera camera;
      camera.setViewportSize(size);
      camera.setAngles(35, 25);
      const glm::vec3 half(30, 20, 10);
      camera.fit(half);
      for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p((corner & 1 ? 1 : -1) * half.x, (corner & 2 ? 1 : -1) * half.y,
                          (corner & 4 ? 1 : -1) * half.z);
        const glm::vec3 px = camera.project(p);
        QVERIFY(px.x > 0 && px.x < size.x && px.y > 0 && px.y < size.y);
        QVERIFY(px.z > camera.nearPlane() && px.z < camera.farPlane());
      }
    }
  }

  // --- Cut geometry --------------------------------------------------------------------------------

  void cutPolygonShapes() {
    const Block block(glm::vec3(40));
    const auto square = cutPolygon(block, CutPlaneSetting{5, 0, 0}.plane());  // x = 5
    QCOMPARE(square.size(), std::size_t(4));
    for (const glm::vec3& p : square) QVERIFY(std::abs(p.x - 5) < 1e-4f);
    const CutPlane diagonal({0, 0, 0}, {1, 1, 1});
    const auto hexagon = cutPolygon(block, diagonal);
    QCOMPARE(hexagon.size(), std::size_t(6));
    // Counter-clockwise seen from the normal's side.
    for (std::size_t i = 0; i < hexagon.size(); ++i) {
      const glm::vec3 a = hexagon[i], b = hexagon[(i + 1) % 6], c = hexagon[(i + 2) % 6];
      QVERIFY(glm::dot(glm::cross(b - a, c - b), diagonal.normal()) > 0);
    }
    QVERIFY(cutPolygon(block, CutPlaneSetting{25, 0, 0}.plane()).empty());
  }

  void gizmoSnapRule() {
    QCOMPARE(CutGizmo::snapAngle(37.0f, true), 30.0f);
    QCOMPARE(CutGizmo::snapAngle(38.0f, true), 45.0f);
    QCOMPARE(CutGizmo::snapAngle(87.5f, false), 90.0f);
    QCOMPARE(CutGizmo::snapAngle(-2.0f, false), 0.0f);
    QCOMPARE(CutGizmo::snapAngle(86.0f, false), 86.0f);
    QCOMPARE(CutGizmo::snapAngle(37.0f, false), 37.0f);
  }

  void gizmoEdgeOnRingAndOffsetLimits() {
    CutGizmo gizmo;
    gizmo.setBlock(Block(glm::vec3(40)));
    gizmo.setSetting({0.0f, 0.0f, 0.0f});  // x = 0, facing +x
    OrbitCamera camera;
    camera.setViewportSize({800, 600});
    camera.fit(glm::vec3(20));
    camera.setView(OrbitCamera::View::Front);  // the horizontal (azimuth) ring is seen edge-on
    auto px = [&](glm::vec3 p) {
      const glm::vec3 q = camera.project(p);
      return glm::vec2(q.x, q.y);
    };
    const float R = gizmo.ringRadius();
    QVERIFY(R > 0);
    // Grab the ring's front half at -100 degrees (clear of the arrow; +100 lies behind it on the same
    // screen line), follow it on screen to -120 degrees.
    const glm::vec2 from = px(gizmo.ringPoint(CutGizmo::Handle::AzimuthRing, glm::radians(-100.0f)));
    QCOMPARE(gizmo.pick(camera, from), CutGizmo::Handle::AzimuthRing);
    QVERIFY(gizmo.beginDrag(CutGizmo::Handle::AzimuthRing, camera, from));
    CutPlaneSetting s;
    for (int deg = -102; deg >= -120; deg -= 2)
      s = gizmo.drag(camera, px(gizmo.ringPoint(CutGizmo::Handle::AzimuthRing, glm::radians(float(deg)))),
                     false);
    gizmo.endDrag();
    qInfo() << "edge-on ring: -20 degrees along the ring turned the azimuth by" << s.azimuthDeg;
    QVERIFY(std::abs(s.azimuthDeg + 20.0f) < 1.0f);
    QVERIFY(std::abs(s.elevationDeg) < 1e-4f);
    // Offset drags stay inside the block.
    gizmo.setSetting({0.0f, 30.0f, 20.0f});
    camera.setAngles(35, 25);
    const glm::vec2 tip = px(gizmo.arrowTip());
    QCOMPARE(gizmo.pick(camera, tip), CutGizmo::Handle::Arrow);
    QVERIFY(gizmo.beginDrag(CutGizmo::Handle::Arrow, camera, tip));
    const glm::vec2 along = glm::normalize(px(gizmo.arrowTip() + gizmo.normal()) - px(gizmo.arrowTip()));
    s = gizmo.drag(camera, tip + 5000.0f * along, false);
    QVERIFY(s.offsetMm > 0.0f);
    QVERIFY(s.offsetMm < gizmo.maxOffset(s.normal()));
    QVERIFY(gizmo.meetsBlock());
    s = gizmo.drag(camera, tip + 7.3f * along, true);  // Shift: whole millimetres
    QCOMPARE(s.offsetMm, std::round(s.offsetMm));
    QCOMPARE(gizmo.cancelDrag(), (CutPlaneSetting{0.0f, 30.0f, 20.0f}));
  }

  // --- The widget ----------------------------------------------------------------------------------

  void blockIsVisible() {
    view_->setCutEnabled(false);
    view_->setShowPhotos(false);
    view_->resetCamera();
    const QImage image = view_->grabFramebuffer();
    QVERIFY(image.save(artifact("block")));
    const int w = image.width(), h = image.height();
    int wood = 0, total = 0;
    for (int y = h * 2 / 5; y < h * 3 / 5; y += 4)
      for (int x = w * 2 / 5; x < w * 3 / 5; x += 4) wood += looksLikeWood(rgbAt(image, x, y)), ++total;
    QVERIFY2(wood > total * 0.9,
             qPrintable(QString("only %1 of %2 centre pixels look like wood").arg(wood).arg(total)));
    for (QPoint corner : {QPoint(3, 3), QPoint(w - 4, 3), QPoint(3, h - 4), QPoint(w - 4, h - 4)}) {
      const glm::vec3 c = rgbAt(image, corner.x(), corner.y());
      QVERIFY2(looksLikeBackground(c), qPrintable(QString("corner %1,%2 is not background: %3 %4 %5")
                                                      .arg(corner.x())
                                                      .arg(corner.y())
                                                      .arg(c.x)
                                                      .arg(c.y)
                                                      .arg(c.z)));
    }
  }

  void fiberHighlight() {
    view_->resetCamera();
    view_->setFiberHighlight(0.0f);
    const QImage matte = view_->grabFramebuffer();
    QVERIFY(matte.save(artifact("no_fiber_highlight")));
    view_->setFiberHighlight(1.0f);
    const QImage finished = view_->grabFramebuffer();
    const double d = meanDifference(matte, finished);
    qInfo() << "fibre highlight: mean difference" << d;
    // What the highlight adds, 8x brighter, to judge its pattern.
    QImage added(matte.size(), QImage::Format_RGB888);
    for (int y = 0; y < added.height(); ++y)
      for (int x = 0; x < added.width(); ++x) {
        const QColor a = finished.pixelColor(x, y), b = matte.pixelColor(x, y);
        auto amp = [](int v) { return std::clamp(v * 8, 0, 255); };
        added.setPixelColor(
            x, y, QColor(amp(a.red() - b.red()), amp(a.green() - b.green()), amp(a.blue() - b.blue())));
      }
    QVERIFY(added.save(artifact("fiber_highlight_x8")));
    // Strongly distorted (figured) wood: the highlight follows the fibres' wobble.
    Project figured = project_;
    figured.params.distortionAmplitude = 2.5f, figured.params.distortionScale = 5.0f;
    figured.rates = synthesizeGrowthRates(figured.params, figured.block);
    view_->setModel(std::make_shared<const WoodModel>(figured));
    view_->refineNow();
    QVERIFY(view_->grabFramebuffer().save(artifact("figured")));
    view_->setModel(model_);
    view_->refineNow();
    QVERIFY(d > 0.002);
  }

  void principalViews() {
    QTest::keyClick(view_.get(), Qt::Key_7);
    QCOMPARE(view_->camera().pitchDeg(), 90.0f);
    QVERIFY(view_->grabFramebuffer().save(artifact("top")));
    QTest::keyClick(view_.get(), Qt::Key_3);
    QCOMPARE(view_->camera().yawDeg(), 90.0f);
    QCOMPARE(view_->camera().pitchDeg(), 0.0f);
    QTest::keyClick(view_.get(), Qt::Key_1, Qt::ControlModifier);
    QCOMPARE(view_->camera().yawDeg(), 180.0f);
    QTest::keyClick(view_.get(), Qt::Key_Home);
    QCOMPARE(view_->camera().yawDeg(), 35.0f);
    QCOMPARE(view_->camera().pitchDeg(), 25.0f);
  }

  void parameterChangesPicture() {
    view_->resetCamera();
    const QImage before = view_->grabFramebuffer();
    Project changed = project_;
    changed.params.latewoodColor = {0.15f, 0.25f, 0.55f};
    changed.params.sapwoodLatewoodColor = {0.15f, 0.25f, 0.55f};
    view_->setModel(std::make_shared<const WoodModel>(changed));
    const QImage after = view_->grabFramebuffer();
    QVERIFY(after.save(artifact("blue_latewood")));
    const double d = meanDifference(before, after);
    qInfo() << "latewood colour change: mean difference" << d;
    QVERIFY(d > 0.01);
    view_->setModel(model_);
    QVERIFY(meanDifference(before, view_->grabFramebuffer()) < 1e-6);
  }

  void cutChangesPicture() {
    view_->resetCamera();
    const QImage whole = view_->grabFramebuffer();
    view_->setCutPlane({4.0f, 20.0f, 30.0f});
    QCOMPARE(view_->grabFramebuffer(), whole);  // the plane alone changes nothing while the cut is off
    view_->setCutSide(Viewport3D::CutSide::Hide);
    view_->setCutEnabled(true);
    const QImage hidden = view_->grabFramebuffer();
    QVERIFY(hidden.save(artifact("cut_hide")));
    QVERIFY(meanDifference(whole, hidden) > 0.01);
    view_->setCutSide(Viewport3D::CutSide::Ghost);
    const QImage ghost = view_->grabFramebuffer();
    QVERIFY(ghost.save(artifact("cut_ghost")));
    QVERIFY(meanDifference(hidden, ghost) > 0.002);
    // The cut surface is wood: the pixel at the centre of the cut surface.
    view_->setCutHandlesVisible(false);
    const QImage plain = view_->grabFramebuffer();
    view_->setCutHandlesVisible(true);
    const glm::vec3 c = view_->camera().project(view_->gizmo().pivot());
    QVERIFY(looksLikeWood(rgbAt(plain, static_cast<int>(c.x) + 6, static_cast<int>(c.y) + 6)));
  }

  void dragOnCutSurfaceMovesPlane() {
    view_->resetCamera();
    view_->setCutSide(Viewport3D::CutSide::Hide);
    view_->setCutEnabled(true);
    view_->setCutPlane({5.0f, 0.0f, 0.0f});  // x = 5, facing +x (face E side, seen by the default view)
    view_->grabFramebuffer();
    const CutGizmo& gizmo = view_->gizmo();
    const OrbitCamera& camera = view_->camera();
    // A point on the cut surface away from the handles: towards a corner of the surface.
    glm::vec3 grab(0.0f);
    bool found = false;
    for (const glm::vec3& corner : gizmo.polygon()) {
      for (float t : {0.8f, 0.65f, 0.5f}) {
        const glm::vec3 p = gizmo.pivot() + t * (corner - gizmo.pivot());
        const glm::vec3 px = camera.project(p);
        if (gizmo.pick(camera, {px.x, px.y}) == CutGizmo::Handle::Surface) {
          grab = p, found = true;
          break;
        }
      }
      if (found) break;
    }
    QVERIFY2(found, "no free spot on the cut surface");
    const glm::vec3 p0 = camera.project(grab);
    const glm::vec3 p1 = camera.project(grab + glm::vec3(1, 0, 0));  // +1 mm along the normal
    const glm::vec2 dir = glm::normalize(glm::vec2(p1) - glm::vec2(p0));

    QSignalSpy spy(view_.get(), &Viewport3D::cutPlaneEdited);
    const QPoint start = toQPoint(p0);
    QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, start);
    for (int i = 1; i <= 6; ++i)
      QTest::mouseMove(view_.get(), start + QPoint(std::lround(dir.x * 8 * i), std::lround(dir.y * 8 * i)));
    QVERIFY(view_->grabFramebuffer().save(artifact("drag_offset")));
    const QPoint end = start + QPoint(std::lround(dir.x * 48), std::lround(dir.y * 48));
    QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, end);

    QVERIFY(spy.count() >= 2);
    for (int i = 0; i + 1 < spy.count(); ++i) QCOMPARE(spy.at(i).at(1).toBool(), false);
    const auto last = spy.takeLast();
    QCOMPARE(last.at(1).toBool(), true);
    const auto setting = last.at(0).value<CutPlaneSetting>();
    qInfo() << "offset after the drag:" << setting.offsetMm << "mm";
    QVERIFY(setting.offsetMm > 6.0f);
    QVERIFY(setting.offsetMm < 20.0f);
    QCOMPARE(setting.azimuthDeg, 0.0f);
    QCOMPARE(setting.elevationDeg, 0.0f);
    QCOMPARE(view_->cutPlane(), setting);
  }

  // Drags `ring` from angle `from` to angle `to` (degrees, along the ring) in small steps.
  QList<QVariantList> dragRing(CutGizmo::Handle ring, float fromDeg, float toDeg,
                               Qt::KeyboardModifiers mods) {
    const CutGizmo& gizmo = view_->gizmo();
    const OrbitCamera& camera = view_->camera();
    QSignalSpy spy(view_.get(), &Viewport3D::cutPlaneEdited);
    auto at = [&](float deg) { return toQPoint(camera.project(gizmo.ringPoint(ring, glm::radians(deg)))); };
    const QPoint start = at(fromDeg);
    if (gizmo.pick(camera, {float(start.x()), float(start.y())}) != ring) {
      qWarning() << "ring not picked at" << start;
      return {};
    }
    QTest::mousePress(view_.get(), Qt::LeftButton, mods, start);
    const CutPlaneSetting startSetting = gizmo.setting();
    for (int i = 1; i <= 12; ++i) {
      const float deg = fromDeg + (toDeg - fromDeg) * i / 12.0f;
      // Ring points move with the pivot only after the drag: keep to the frame the drag began in.
      QTest::mouseEvent(QTest::MouseMove, view_.get(), Qt::NoButton, mods, at(deg));
    }
    Q_UNUSED(startSetting);
    QTest::mouseRelease(view_.get(), Qt::LeftButton, mods, at(toDeg));
    QList<QVariantList> out;
    for (const auto& args : spy) out.append(args);
    return out;
  }

  void shiftRotationSnapsTo15Degrees() {
    view_->resetCamera();
    view_->setCutSide(Viewport3D::CutSide::Ghost);
    view_->setCutEnabled(true);
    view_->setCutPlane({0.0f, 0.0f, 0.0f});
    view_->grabFramebuffer();
    // Azimuth ring, 37 degrees with Shift: 30.
    auto signals_ = dragRing(CutGizmo::Handle::AzimuthRing, 120.0f, 157.0f, Qt::ShiftModifier);
    QVERIFY(!signals_.isEmpty());
    auto s = signals_.last().at(0).value<CutPlaneSetting>();
    QCOMPARE(signals_.last().at(1).toBool(), true);
    qInfo() << "azimuth after a 37 degree Shift-drag:" << s.azimuthDeg;
    QVERIFY(std::abs(s.azimuthDeg - 30.0f) < 1e-3f);
    for (const auto& args : signals_) {
      const auto step = args.at(0).value<CutPlaneSetting>();
      QVERIFY(std::abs(std::remainder(step.azimuthDeg, 15.0f)) < 1e-3f);
      QCOMPARE(step.elevationDeg, 0.0f);
    }
    QVERIFY(view_->grabFramebuffer().save(artifact("rotated_az30")));

    // Elevation ring, 52 degrees with Shift: 45 (the plane keeps passing through the pivot).
    const glm::vec3 pivot = view_->gizmo().pivot();
    signals_ = dragRing(CutGizmo::Handle::ElevationRing, -50.0f, 2.0f, Qt::ShiftModifier);
    QVERIFY(!signals_.isEmpty());
    s = signals_.last().at(0).value<CutPlaneSetting>();
    qInfo() << "elevation after a 52 degree Shift-drag:" << s.elevationDeg << "azimuth" << s.azimuthDeg;
    QVERIFY(std::abs(s.elevationDeg - 45.0f) < 1e-3f);
    QVERIFY(std::abs(s.azimuthDeg - 30.0f) < 1e-3f);
    QVERIFY(std::abs(glm::dot(pivot, s.normal()) - s.offsetMm) < 1e-3f);
    QVERIFY(view_->grabFramebuffer().save(artifact("rotated_az30_el45")));
  }

  void rotationSnapsToPrincipalPlanes() {
    view_->resetCamera();
    view_->setCutEnabled(true);
    view_->setCutPlane({0.0f, 0.0f, 0.0f});
    view_->grabFramebuffer();
    // Without Shift: 88 degrees of elevation snaps to 90 (a cross-section), 40 stays 40.
    auto signals_ = dragRing(CutGizmo::Handle::ElevationRing, -60.0f, 28.0f, Qt::NoModifier);
    QVERIFY(!signals_.isEmpty());
    auto s = signals_.last().at(0).value<CutPlaneSetting>();
    QVERIFY2(std::abs(s.elevationDeg - 90.0f) < 1e-3f, qPrintable(QString::number(s.elevationDeg)));
    view_->setCutPlane({0.0f, 0.0f, 0.0f});
    view_->grabFramebuffer();
    signals_ = dragRing(CutGizmo::Handle::ElevationRing, -60.0f, -20.0f, Qt::NoModifier);
    QVERIFY(!signals_.isEmpty());
    s = signals_.last().at(0).value<CutPlaneSetting>();
    QVERIFY2(std::abs(s.elevationDeg - 40.0f) < 0.5f, qPrintable(QString::number(s.elevationDeg)));
  }

  void escapeCancelsDrag() {
    view_->resetCamera();
    view_->setCutEnabled(true);
    view_->setCutPlane({2.0f, 0.0f, 0.0f});
    view_->grabFramebuffer();
    const CutGizmo& gizmo = view_->gizmo();
    const OrbitCamera& camera = view_->camera();
    const QPoint start = toQPoint(camera.project(gizmo.arrowTip()));
    QCOMPARE(gizmo.pick(camera, {float(start.x()), float(start.y())}), CutGizmo::Handle::Arrow);
    QSignalSpy spy(view_.get(), &Viewport3D::cutPlaneEdited);
    QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, start);
    QTest::mouseMove(view_.get(), start + QPoint(30, 0));
    QTest::mouseMove(view_.get(), start + QPoint(60, 0));
    QTest::keyClick(view_.get(), Qt::Key_Escape);
    QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, start + QPoint(60, 0));
    QVERIFY(spy.count() >= 2);
    QCOMPARE(spy.last().at(1).toBool(), true);
    QCOMPARE(spy.last().at(0).value<CutPlaneSetting>(), (CutPlaneSetting{2.0f, 0.0f, 0.0f}));
    QCOMPARE(view_->cutPlane(), (CutPlaneSetting{2.0f, 0.0f, 0.0f}));
  }

  void hoverRedrawsOnlyTheOverlay() {
    view_->resetCamera();
    view_->setCutEnabled(true);
    view_->setCutPlane({0.0f, 0.0f, 0.0f});
    view_->grabFramebuffer();
    const QPoint ring = toQPoint(view_->camera().project(
        view_->gizmo().ringPoint(CutGizmo::Handle::AzimuthRing, glm::radians(130.0f))));
    QTest::mouseMove(view_.get(), ring);
    const QImage hovered = view_->grabFramebuffer();
    QVERIFY(!view_->lastFrameRenderedScene());
    QVERIFY(hovered.save(artifact("hover_ring")));
    QTest::mouseMove(view_.get(), QPoint(5, 5));
  }

  void orbitDragRendersReducedThenRefines() {
    view_->setCutEnabled(false);
    view_->setReducedResolutionDivisor(3);
    // The refine timer may not fire between the drag and the grab, however slow the machine: a minute.
    view_->setRefineDelayMs(60000);
    view_->resetCamera();
    view_->grabFramebuffer();
    QCOMPARE(view_->lastFrameDivisor(), 1);  // a key-press-like change renders full resolution
    const float yaw = view_->camera().yawDeg();
    QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, QPoint(20, 20));
    QTest::mouseMove(view_.get(), QPoint(60, 30));
    QVERIFY(view_->camera().yawDeg() < yaw);  // dragging right turns the block right
    const QImage reduced = view_->grabFramebuffer();
    QCOMPARE(view_->lastFrameDivisor(), 3);
    QVERIFY(reduced.save(artifact("orbit_reduced")));
    QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, QPoint(60, 30));
    view_->setRefineDelayMs(150);  // restarts the pending refine with this delay
    QTRY_VERIFY_WITH_TIMEOUT(view_->lastFrameDivisor() == 1, 20000);
    view_->setReducedResolutionDivisor(1);
    view_->setRefineDelayMs(200);
  }

  void photosProjectOntoFaces() {
    view_->resetCamera();
    view_->setCutEnabled(false);
    view_->setFiberHighlight(0.0f);  // photos have no fibre directions: compare like with like
    const QImage modelPicture = view_->grabFramebuffer();
    std::array<QImage, 6> photos, mirrored;
    for (FaceId face : kAllFaces) {
      const glm::ivec2 size = model_->block().faceImageSize(face, 6.0f);
      photos[faceIndex(face)] = toQImage(renderFace(*model_, face, size));
      mirrored[faceIndex(face)] = photos[faceIndex(face)].mirrored(true, false);
    }
    view_->setFacePhotos(photos);
    view_->setShowPhotos(true);
    const QImage photoPicture = view_->grabFramebuffer();
    QVERIFY(photoPicture.save(artifact("photos")));
    view_->setFacePhotos(mirrored);
    const QImage mirroredPicture = view_->grabFramebuffer();
    const double same = meanDifference(modelPicture, photoPicture);
    const double wrong = meanDifference(modelPicture, mirroredPicture);
    qInfo() << "photos vs model: mean difference" << same << "(mirrored photos:" << wrong << ")";
    QVERIFY(same < 0.015);
    QVERIFY(same < 0.25 * wrong);
    view_->setShowPhotos(false);
    view_->setFiberHighlight(1.0f);
  }

  // More pictures to judge by eye: the cut seen from the kept side, a board, zoomed in.
  void morePictures() {
    view_->setCutSide(Viewport3D::CutSide::Hide);
    view_->setCutEnabled(true);
    view_->setCutPlane({3.0f, 30.0f, 20.0f});
    OrbitCamera behind = view_->camera();
    behind.setAngles(215.0f, -20.0f);
    view_->setCamera(behind);
    QVERIFY(view_->grabFramebuffer().save(artifact("cut_from_behind")));

    Project board = project_;
    board.block = Block(glm::vec3(160.0f, 30.0f, 60.0f));  // a short board
    board.rates = synthesizeGrowthRates(board.params, board.block);
    view_->setModel(std::make_shared<const WoodModel>(board));
    view_->resetCamera();
    view_->setCutSide(Viewport3D::CutSide::Ghost);
    view_->setCutPlane({40.0f, 10.0f, 0.0f});
    QVERIFY(view_->grabFramebuffer().save(artifact("board")));
    // Zoomed towards a corner with the wheel, then panned.
    const QPoint corner = toQPoint(view_->camera().project(glm::vec3(80, 15, 30)));
    for (int i = 0; i < 4; ++i) {
      QWheelEvent wheel(corner, view_->mapToGlobal(corner), QPoint(), QPoint(0, 120), Qt::NoButton,
                        Qt::NoModifier, Qt::NoScrollPhase, false);
      QApplication::sendEvent(view_.get(), &wheel);
    }
    const glm::vec3 after = view_->camera().project(glm::vec3(80, 15, 30));
    QVERIFY2(std::abs(after.x - corner.x()) < 1.5f && std::abs(after.y - corner.y()) < 1.5f,
             "the wheel does not zoom towards the cursor");
    view_->refineNow();
    QVERIFY(view_->grabFramebuffer().save(artifact("board_zoomed")));

    // After a drag the picture refines by itself.
    view_->setModel(model_);
    view_->resetCamera();
    view_->setCutEnabled(false);
    view_->setReducedResolutionDivisor(3);
    view_->setRefineDelayMs(
        60000);  // no refine before the reduced frame is checked, however slow the machine
    QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, QPoint(20, 20));
    QTest::mouseMove(view_.get(), QPoint(24, 20));
    QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, QPoint(24, 20));
    view_->grabFramebuffer();  // reduced
    QTRY_VERIFY(!view_->fullyRefined() && view_->lastFrameRenderedScene() && view_->lastFrameDivisor() == 3);
    view_->setRefineDelayMs(200);  // the default: the pending refine restarts with it
    QTRY_VERIFY_WITH_TIMEOUT(view_->fullyRefined(), 20000);
    view_->setReducedResolutionDivisor(1);
  }

  // Inside a window with other widgets, QWidget::grab() (the editor's --screenshot) shows the wood.
  void embeddedInWindow() {
    QWidget window;
    auto* layout = new QHBoxLayout(&window);
    auto* label = new QLabel("parameters");
    auto* view = new Viewport3D;
    layout->addWidget(label);
    layout->addWidget(view, 1);
    view->setModel(model_);
    window.resize(700, 450);
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QTRY_VERIFY(view->ready());
    const QImage shot = window.grab().toImage();
    QVERIFY(shot.save(artifact("embedded")));
    const QPoint centre = view->geometry().center();
    QVERIFY(looksLikeWood(rgbAt(shot, centre.x(), centre.y())));
  }

  // Frame times at 1280 x 800 (printed for docs/performance.md).
  void frameTimes() { measureFrameTimes("demo block"); }

  // The same in log mode: the board of a random log, its knot model evaluated per fragment
  // (shaders/board_wood.glsl), the knots culled per cell of the board's grid.
  void logModeFrameTimes() {
    const LogModel log = generateRandomLog({.seed = 7});
    measureLogMode(log, woodColorMapFromParameters(WoodParameters{}, log.stem.maxRadius()), "random log 7");
  }

  // The CT-measured spruce log (108 knots, 16 of them reach the default board), where shared/data has it.
  void spruceLogFrameTimes() {
    const LogModel* gran = kerf::testing::granLog();
    if (!gran) QSKIP("the spruce log (shared/data/logs/spruce-gran1) is absent");
    measureLogMode(*gran, gran->colorMap, "spruce log Gran_1");
  }

 private:
  void measureLogMode(const LogModel& log, const WoodColorMap& colors, const QString& name) {
    const Board board = defaultBoard(log);
    // What the editor does on the GUI thread for a knot edit (the field) and a board move (the grid).
    QElapsedTimer clock;
    clock.start();
    auto field = std::make_shared<const KnotField>(log, KnotSettings{});
    const double fieldMs = clock.nsecsElapsed() * 1e-6;
    clock.restart();
    const KnotCellGrid grid = buildKnotCellGrid(*field, board, knotGridCells(board.size));
    const double gridMs = clock.nsecsElapsed() * 1e-6;
    const auto wood = std::make_shared<const BoardWood>(
        BoardWood{std::move(field), std::make_shared<const WoodColorMap>(colors), board});
    Project project;
    project.block = Block(board.size);
    view_->setModel(std::make_shared<const WoodModel>(project));
    view_->setBoardWood(wood);
    view_->resize(1280, 800);
    view_->resetCamera();
    clock.restart();
    // The first frame uploads the log's tables (and, the view's first time in log mode, builds the program).
    const QImage picture = view_->grabFramebuffer();
    const double firstMs = clock.nsecsElapsed() * 1e-6;
    QVERIFY(picture.save(artifact("log_mode_" + QString(name).replace(' ', '_'))));
    const glm::vec3 centre = rgbAt(picture, picture.width() / 2, picture.height() / 2);
    QVERIFY2(looksLikeWood(centre), "the board should show wood at the view's centre");
    qInfo().noquote() << QString(
                             "%1: %2 knots, %3 can reach the board, %4 cells, %5 knots per cell; "
                             "knot field %6 ms, grid %7 ms, first frame %8 ms")
                             .arg(name)
                             .arg(log.knots.size())
                             .arg(grid.boardKnots)
                             .arg(grid.ranges.size())
                             .arg(grid.meanKnotsPerCell(), 0, 'f', 2)
                             .arg(fieldMs, 0, 'f', 1)
                             .arg(gridMs, 0, 'f', 1)
                             .arg(firstMs, 0, 'f', 1);
    measureFrameTimes("log mode, default board of the " + name);
    view_->setBoardWood(nullptr);
    view_->setModel(model_);
  }

  void measureFrameTimes(const QString& what) {
    qInfo().noquote() << "frame times:" << what;
    view_->resize(1280, 800);
    QTest::qWait(50);
    view_->setCutEnabled(false);
    view_->resetCamera();
    view_->setFinishFrames(true);
    double lastMs = 0.0;
    connect(view_.get(), &Viewport3D::frameRendered, this, [&](double ms) { lastMs = ms; });
    int missed = 0;
    auto measure = [&](int frames, const std::function<void(int)>& change) {
      std::vector<double> times;
      for (int i = 0; i < frames; ++i) {
        change(i);
        view_->grabFramebuffer();
        missed += !view_->lastFrameRenderedScene();
        times.push_back(lastMs);
      }
      return times;
    };
    auto nudge = [&](int i) {
      OrbitCamera camera = view_->camera();
      camera.setAngles(camera.yawDeg() + (i % 2 ? 0.5f : -0.5f), camera.pitchDeg());
      view_->setCamera(camera);
    };
    view_->setReducedResolutionDivisor(1);
    view_->grabFramebuffer();
    QCOMPARE(view_->width(), 1280);
    const double full = median(measure(7, nudge));
    view_->setCutPlane({3.0f, 25.0f, 20.0f});
    view_->setCutSide(Viewport3D::CutSide::Ghost);
    view_->setCutEnabled(true);
    const double fullCut = median(measure(5, nudge));
    view_->setCutEnabled(false);
    // Interactive frames: an orbit drag, as the user does it.
    auto orbitStep = [&](int i) { QTest::mouseMove(view_.get(), QPoint(40 + (i % 2) * 3, 40)); };
    auto interactive = [&](int divisor) {
      view_->setReducedResolutionDivisor(divisor);
      QTest::mousePress(view_.get(), Qt::LeftButton, Qt::NoModifier, QPoint(40, 40));
      const double ms = median(measure(9, orbitStep));
      const int used = view_->lastFrameDivisor();
      QTest::mouseRelease(view_.get(), Qt::LeftButton, Qt::NoModifier, QPoint(40, 40));
      return std::make_pair(ms, used);
    };
    const auto half = interactive(2);
    const auto third = interactive(3);
    const auto automatic = interactive(0);
    // The refinement after that drag: full resolution in bands, one per frame.
    std::vector<double> bands;
    auto collect = connect(view_.get(), &Viewport3D::frameRendered, this, [&](double ms) {
      if (view_->lastFrameRenderedScene()) bands.push_back(ms);
    });
    QTRY_VERIFY_WITH_TIMEOUT(view_->fullyRefined(), 10000);
    disconnect(collect);
    const double longestBand = bands.empty() ? 0.0 : *std::max_element(bands.begin(), bands.end());
    qInfo().noquote() << QString("GL_RENDERER: %1").arg(view_->rendererName());
    qInfo().noquote() << QString("frame 1280x800 full resolution: %1 ms (cut + ghost: %2 ms)")
                             .arg(full, 0, 'f', 1)
                             .arg(fullCut, 0, 'f', 1);
    qInfo().noquote() << QString(
                             "interactive 1/2 (640x400): %1 ms; 1/3 (427x267): %2 ms; automatic: 1/%3, %4 ms")
                             .arg(half.first, 0, 'f', 1)
                             .arg(third.first, 0, 'f', 1)
                             .arg(automatic.second)
                             .arg(automatic.first, 0, 'f', 1);
    qInfo().noquote() << QString("refinement after the drag: %1 bands, longest %2 ms")
                             .arg(bands.size())
                             .arg(longestBand, 0, 'f', 1);
    QCOMPARE(missed, 0);
    QVERIFY(half.second == 2 && third.second == 3);
    QVERIFY(third.first < full);
    view_->setFinishFrames(false);
    view_->setReducedResolutionDivisor(1);
    disconnect(view_.get(), &Viewport3D::frameRendered, this, nullptr);
  }

  Project project_;
  std::shared_ptr<const WoodModel> model_;
  std::unique_ptr<Viewport3D> view_;
};

QTEST_MAIN(Viewport3DTest)
#include "test_viewport3d.moc"
