// A placed part in the live 3D view (issue 7): Viewport3D::setPart draws the mesh inside the ghosted
// block, coloured by the GLSL wood model, under a real OpenGL context (Mesa under xvfb-run).
#include <QtTest>
#include <cmath>
#include <memory>

#include "../app/image_change.hpp"
#include "demo/demo_block.hpp"
#include "mesh/part_placement.hpp"
#include "viewport3d.hpp"

using namespace kerf;
using kerf::testing::changedShare;

namespace {

QString artifact(const QString& name) {
  return QStringLiteral(KERF_TEST_ARTIFACTS) + "/part_view_" + name + ".png";
}

// A turned part (a small candlestick, 34 mm tall, solid of revolution about y with flat ends), tilted
// 20° about x so the rings cross it at an angle.
std::shared_ptr<const Mesh> placedTurnedPart() {
  Mesh m;
  m.name = "candlestick";
  const int sides = 64, rows = 48;
  const auto radius = [](float t) {  // t from the foot (0) to the top (1), mm
    return 6.5f + 4.0f * std::exp(-std::pow((t - 0.04f) / 0.08f, 2.0f)) -
           3.0f * std::pow(std::sin(float(M_PI) * t), 2.0f) +
           2.5f * std::exp(-std::pow((t - 0.62f) / 0.05f, 2.0f)) + 3.0f * std::pow(t, 4.0f);
  };
  for (int r = 0; r < rows; ++r) {
    const float t = float(r) / (rows - 1);
    for (int i = 0; i < sides; ++i) {
      const float a = 2.0f * float(M_PI) * i / sides;
      m.positions.push_back({radius(t) * std::cos(a), -17.0f + 34.0f * t, -radius(t) * std::sin(a)});
    }
  }
  for (unsigned r = 0; r + 1 < unsigned(rows); ++r)
    for (unsigned i = 0; i < unsigned(sides); ++i) {
      const unsigned a = r * sides + i, b = r * sides + (i + 1) % sides;
      m.triangles.push_back({a, b, b + sides});
      m.triangles.push_back({a, b + sides, a + sides});
    }
  const unsigned bottom = unsigned(m.positions.size()), top = bottom + 1;
  m.positions.push_back({0, -17, 0});
  m.positions.push_back({0, 17, 0});
  for (unsigned i = 0; i < unsigned(sides); ++i) {
    m.triangles.push_back({bottom, (i + 1) % sides, i});
    const unsigned last = (rows - 1) * sides;
    m.triangles.push_back({top, last + i, last + (i + 1) % sides});
  }
  PartPlacement p;
  p.rotationDeg = {20, 0, 0};
  return std::make_shared<const Mesh>(placeMesh(m, p));  // no normals: drawn flat per triangle
}

}  // namespace

class PartViewTest : public QObject {
  Q_OBJECT

 private slots:
  void partChangesThePictureAndShowsWood() {
    const Project project = demoProject();
    Viewport3D view;
    view.resize(700, 520);
    view.setModel(std::make_shared<const WoodModel>(project));
    view.setReducedResolutionDivisor(1);
    view.show();
    QVERIFY(QTest::qWaitForWindowExposed(&view));
    view.grabFramebuffer();
    QVERIFY2(view.ready(), "the 3D view's shaders did not build (run under xvfb-run with Mesa)");
    view.refineNow();
    const QImage block = view.grabFramebuffer();

    const auto part = placedTurnedPart();
    view.setPart(part);
    QVERIFY(view.showsPart());
    view.refineNow();
    const QImage withPart = view.grabFramebuffer();
    QVERIFY(withPart.save(artifact("turned")));
    const double share = changedShare(block, withPart);
    qInfo() << "share of pixels changed by showing the part:" << share;
    QVERIFY(share > 0.1);

    // The part's centre (the block centre) is wood seen through the ghost: warm, not the grey ghost.
    const glm::vec3 c = view.camera().project(glm::vec3(0.0f));
    const QColor centre = withPart.pixelColor(int(c.x), int(c.y));
    qInfo() << "part centre pixel" << centre;
    QVERIFY(centre.redF() > centre.greenF() && centre.greenF() > centre.blueF());
    QVERIFY(centre.redF() - centre.blueF() > 0.1);
    // Beside the part, inside the block's outline, the ghost shows the background through it: greyer
    // than the opaque block there.
    const glm::vec3 corner = view.camera().project(glm::vec3(16.0f, 16.0f, 16.0f));
    const QColor ghost = withPart.pixelColor(int(corner.x), int(corner.y));
    const QColor opaque = block.pixelColor(int(corner.x), int(corner.y));
    QVERIFY(ghost.redF() - ghost.blueF() < opaque.redF() - opaque.blueF());

    // Taking the part away gives the block back exactly.
    view.setPart(nullptr);
    view.refineNow();
    QCOMPARE(changedShare(block, view.grabFramebuffer()), 0.0);
  }
};

QTEST_MAIN(PartViewTest)
#include "test_part_view.moc"
