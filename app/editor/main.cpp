// kerf [PROJECT|SAMPLE_FOLDER] [--screenshot FILE]: the desktop editor. Without a document it shows its
// start page (with --screenshot it opens the bundled demo); with --screenshot it saves the window once the
// faces have rendered and exits
// (used by the tests and for the README's picture).
#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>
#include <QSurfaceFormat>
#include <QTimer>
#include <cstdio>

#include "gpu/surface_format.hpp"
#include "main_window.hpp"
#include "viewport3d.hpp"
#include "window_grab.hpp"

namespace {

void fail(const QString& message) {
  std::fprintf(stderr, "kerf: %s\n", qPrintable(message));
  QCoreApplication::exit(1);
}

void grabWhenDrawn(kerf::MainWindow& window, const QString& file) {
  window.viewport()->refineNow();
  // Give the GL views a few event-loop turns to draw their full-resolution frames.
  QTimer::singleShot(400, &window, [&window, file] {
    QDir().mkpath(QFileInfo(file).absolutePath());
    if (kerf::grabWindowWithGl(&window).save(file)) {
      QCoreApplication::exit(0);
    } else {
      fail(QStringLiteral("cannot write the screenshot %1").arg(file));
    }
  });
}

// Saves the window once the document is ready, its photo-true surfaces made (a project that shows them)
// and the 3D view has drawn at full resolution; exits 0 on success, 1 on any failure.
void screenshotWhenReady(kerf::MainWindow& window, const QString& file) {
  QObject::connect(&window, &kerf::MainWindow::documentReady, &window, [&window, file] {
    auto* settled = new QTimer(&window);
    settled->start(100);
    QObject::connect(settled, &QTimer::timeout, &window, [&window, file, settled] {
      if (window.appearance()->isWorking()) return;
      settled->stop();
      settled->deleteLater();
      grabWhenDrawn(window, file);
    });
  });
  QObject::connect(&window, &kerf::MainWindow::documentFailed, &window, &fail);
}

}  // namespace

int main(int argc, char** argv) {
  kerf::useKerfSurfaceFormat();  // as the editor does
  QApplication app(argc, argv);
  QApplication::setApplicationName(QStringLiteral("Kerf"));
  QApplication::setOrganizationName(QStringLiteral("Kerf"));
  QApplication::setApplicationVersion(QStringLiteral(KERF_VERSION));

  QCommandLineParser parser;
  parser.setApplicationDescription(
      QStringLiteral("Kerf: an editor for the procedural appearance of solid wood."));
  parser.addHelpOption();
  parser.addVersionOption();
  parser.addPositionalArgument(
      QStringLiteral("document"),
      QStringLiteral("A .kerf project or a Mokume-style sample folder (default: the start page)."),
      QStringLiteral("[PROJECT|SAMPLE_FOLDER]"));
  const QCommandLineOption screenshot(
      QStringLiteral("screenshot"),
      QStringLiteral("Save the window to FILE once the faces have rendered, then exit."),
      QStringLiteral("FILE"));
  parser.addOption(screenshot);
  parser.process(app);
  const QStringList documents = parser.positionalArguments();
  if (documents.size() > 1) {
    std::fprintf(stderr, "kerf: at most one document, got %lld\n", static_cast<long long>(documents.size()));
    return 2;
  }

  // Screenshots show the default layout, whatever the user last arranged.
  if (parser.isSet(screenshot)) qputenv("KERF_DEFAULT_LAYOUT", "1");
  kerf::MainWindow window;
  if (parser.isSet(screenshot)) screenshotWhenReady(window, parser.value(screenshot));
  window.show();
  // Start from the event loop, so the window is up before the (possibly slow) demo generation.
  const bool offerRecovery = !parser.isSet(screenshot) && qEnvironmentVariableIsEmpty("KERF_NO_RECOVERY");
  const bool screenshotting = parser.isSet(screenshot);
  QTimer::singleShot(0, &window, [&window, documents, offerRecovery, screenshotting] {
    if (offerRecovery) window.offerRecovery();  // may open the recovered document instead
    if (window.hasDocument()) return;
    if (!documents.isEmpty()) {
      window.openDocument(documents.front());
    } else if (screenshotting) {  // a screenshot needs a document: the demo
      window.openDemo(kerf::defaultDemoFolder());
    }  // else the start page: photos, a project, the demo or a recent file
  });
  return app.exec();
}
