// A placed part in the live 3D view (issue 7): Viewport3D::setPart draws the mesh inside the ghosted
// block, coloured by the GLSL wood model, under a real OpenGL context (Mesa under xvfb-run).
#include <QtTest>
#include <cmath>
#include <memory>

#include "demo/demo_block.hpp"
#include "mesh/part_placement.hpp"
#include "viewport3d.hpp"

using namespace kerf;

namespace {

QString artifact(const QString& name) {
  return QStringLiteral(KERF_TEST_ARTIFACTS) + "/part_view_" + name + ".png";
}

// An open 48-sided tube along y (radius 9 mm, 26 mm long), turned 30° about x.
std::shared_ptr<const Mesh> placedCylinder() {
  Mesh m;
  m.name = "cylinder";
  const int sides = 48;
  for (int i = 0; i < sides; ++i) {
    const float a = 2.0f * float(M_PI) * i / sides;
    const glm::vec3 n(std::cos(a), 0, -std::sin(a));
    m.positions.push_back(9.0f * n + glm::vec3(0, -13, 0));
    m.positions.push_back(9.0f * n + glm::vec3(0, 13, 0));
    m.normals.push_back(n);
    m.normals.push_back(n);
  }
  for (unsigned i = 0; i < unsigned(sides); ++i) {
    const unsigned j = (i + 1) % sides;
    m.triangles.push_back({2 * i, 2 * j, 2 * j + 1});
    m.triangles.push_back({2 * i, 2 * j + 1, 2 * i + 1});
  }
  PartPlacement p;
  p.rotationDeg = {30, 0, 0};
  return std::make_shared<const Mesh>(placeMesh(m, p));
}

double changedShare(const QImage& a, const QImage& b) {
  const QImage x = a.convertToFormat(QImage::Format_RGB32), y = b.convertToFormat(QImage::Format_RGB32);
  if (x.size() != y.size()) return 1.0;
  int changed = 0;
  for (int row = 0; row < x.height(); ++row)
    for (int col = 0; col < x.width(); ++col) {
      const QRgb p = x.pixel(col, row), q = y.pixel(col, row);
      changed +=
          std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q)) > 24;
    }
  return double(changed) / (x.width() * x.height());
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

    const auto part = placedCylinder();
    view.setPart(part);
    QVERIFY(view.showsPart());
    view.refineNow();
    const QImage withPart = view.grabFramebuffer();
    QVERIFY(withPart.save(artifact("cylinder")));
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
