// Measures the editor's interactive latency on this machine: from a parameter edit (what a slider
// sends) to the next 3D frame and to the faces view's preview and full-resolution renderings, in a
// 1280x800 window. (The 3D view's frame time alone is measured by tests/widgets/test_viewport3d.)
// Run under a display (xvfb-run); prints a table. Not a test: numbers depend on the machine.
#include <QApplication>
#include <QElapsedTimer>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QTemporaryDir>
#include <QtTest>
#include <algorithm>
#include <cstdio>
#include <vector>

#include "demo/demo_block.hpp"
#include "document.hpp"
#include "gpu/surface_format.hpp"
#include "main_window.hpp"
#include "viewport3d.hpp"

using namespace kerf;

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();  // as the editor does
  QApplication app(argc, argv);
  QApplication::setOrganizationName("KerfBench");
  QTemporaryDir dir;
  qputenv("KERF_AUTOSAVE_DIR", dir.filePath("autosave").toUtf8());
  DemoOptions options;
  options.facePixels = 256;
  const std::string project = writeDemo(dir.filePath("demo").toStdString(), options).project.string();

  MainWindow window;  // the editor's own settings: 256 px faces, 2x2 samples
  window.setAskBeforeDiscarding(false);
  window.resize(1280, 800);
  window.show();
  QSignalSpy ready(&window, &MainWindow::documentReady);
  window.openDocument(QString::fromStdString(project));
  if (!ready.wait(120000)) return 1;

  Viewport3D* viewport = window.viewport();
  viewport->setFinishFrames(true);  // glFinish inside the timing: honest on any driver
  std::vector<double> frame;
  QTest::qWait(500);
  QObject::connect(viewport, &Viewport3D::frameRendered, [&](double ms) { frame.push_back(ms); });

  // Edit -> next 3D frame (reduced resolution while edits stream) and -> faces preview / full faces.
  std::vector<double> toFrame, toFacesPreview, toFacesFull;
  const std::size_t index = *parameterIndex("growth.ring_width");
  for (int i = 0; i < 7; ++i) {
    frame.clear();
    QSignalSpy faces(&window, &MainWindow::facesRendered);
    QSignalSpy previewed(&window, &MainWindow::facesPreviewed);
    QElapsedTimer clock;
    clock.start();
    window.document()->editParameter(index, {2.5f + 0.1f * i, 0, 0}, true);
    while (frame.empty()) QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    toFrame.push_back(clock.nsecsElapsed() / 1e6);
    while (previewed.isEmpty()) QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
    toFacesPreview.push_back(clock.nsecsElapsed() / 1e6);
    if (faces.isEmpty() && !faces.wait(60000)) return 1;
    toFacesFull.push_back(clock.nsecsElapsed() / 1e6);
  }
  std::printf("renderer: %s\n", qPrintable(viewport->rendererName()));
  std::printf("window 1280x800; 3D view %dx%d\n", viewport->width(), viewport->height());
  std::printf("parameter edit -> next 3D frame: median %.1f ms (7 edits)\n", median(toFrame));
  std::printf("parameter edit -> first faces preview (quarter resolution): median %.1f ms\n",
              median(toFacesPreview));
  std::printf(
      "parameter edit -> faces re-rendered at full resolution (6 x 256 px, 2x2 samples): median %.1f ms\n",
      median(toFacesFull));
  return 0;
}
