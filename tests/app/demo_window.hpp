#pragma once
// The editor on a freshly written demo block, for the editor tests: the demo's photos at `facePixels`
// a side (the model's faces rendered at the same resolution), the window shown at `size` and the document
// loaded; `knot`: with the demo's knot (DemoOptions::knot) and its two marks. Null if the window never
// showed or the demo did not load within the timeout.
#include <QSignalSpy>
#include <QtTest>
#include <memory>

#include "demo/demo_block.hpp"
#include "main_window.hpp"

namespace kerf::testing {

// Where an editor test saves a picture: KERF_TEST_ARTIFACTS_DIR/<name>.png.
inline QString artifact(const QString& name) {
  return QStringLiteral(KERF_TEST_ARTIFACTS_DIR "/") + name + ".png";
}

inline std::unique_ptr<MainWindow> openDemoWindow(const QString& folder, int facePixels, QSize size = {},
                                                  int timeoutMs = 120000, bool knot = false) {
  DemoOptions options;
  options.facePixels = facePixels;
  options.samples = 1;
  options.knot = knot;
  const QString project = QString::fromStdString(writeDemo(folder.toStdString(), options).project.string());
  const float pxPerMm = facePixels / demoProject().block.size().x;  // faces as sharp as the photos
  auto window = std::make_unique<MainWindow>(RenderSettings{pxPerMm, 1});
  window->setAskBeforeDiscarding(false);
  if (size.isValid()) window->resize(size);
  window->show();
  if (!QTest::qWaitForWindowExposed(window.get())) return nullptr;
  QSignalSpy ready(window.get(), &MainWindow::documentReady);
  window->openDocument(project);
  if (!QTest::qWaitFor([&] { return ready.count() > 0; }, timeoutMs)) return nullptr;
  return window;
}

}  // namespace kerf::testing
