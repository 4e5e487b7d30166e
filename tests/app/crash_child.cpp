// The editor in a child process that the crash tests kill with SIGKILL (test_crash_recovery.cpp).
//   crash_child fit PROJECT   opens PROJECT, edits the ring width to 5.5 mm, writes the autosave copy,
//                             detects rings, starts Fit Growth Field and prints "fitting" while it runs
//   crash_child save PROJECT  opens PROJECT, attaches a random log (megabytes of JSON, so a save takes a
//                             while) and saves it over and over (Ctrl+S), the ring width alternating
//                             between 2 and 3 mm, printing "saved N" after each save
//   crash_child export PROJECT OUT   opens PROJECT and exports a 320^3 colour volume to OUT (.nrrd),
//                             printing "exporting" once the export job runs and "exported" when done
// It never exits by itself: the parent kills it.
#include <QApplication>
#include <QTimer>
#include <cstdio>

#include "autosave.hpp"
#include "document.hpp"
#include "export/export_job.hpp"
#include "main_window.hpp"
#include "params/parameter_schema.hpp"

using namespace kerf;

namespace {
void say(const char* line) {
  std::printf("%s\n", line);
  std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  if (argc < 3) {
    std::fprintf(stderr, "usage: crash_child fit|save PROJECT, crash_child export PROJECT OUT\n");
    return 2;
  }
  const QString mode = QString::fromLocal8Bit(argv[1]);
  MainWindow window(RenderSettings{1.6f, 1});
  window.setAskBeforeDiscarding(false);
  const std::size_t ring = *parameterIndex("growth.ring_width");

  QObject::connect(&window, &MainWindow::documentFailed, [](const QString& message) {
    std::fprintf(stderr, "crash_child: %s\n", qPrintable(message));
    QCoreApplication::exit(3);
  });
  QObject::connect(&window, &MainWindow::ringJobFailed, [](const QString& message) {
    std::fprintf(stderr, "crash_child: %s\n", qPrintable(message));
    QCoreApplication::exit(3);
  });
  bool started = false;
  QObject::connect(&window, &MainWindow::documentReady, [&] {
    if (started) return;  // a later re-render
    started = true;
    if (mode == "fit") {
      window.document()->editParameter(ring, {5.5f, 0, 0}, true);
      window.autosave()->saveNow();
      say("autosaved");
      window.rings()->detectRings();
    } else if (mode == "export" && argc == 4) {
      ExportRequest request;
      request.out = argv[3];
      request.quantity = VolumeQuantity::Color;
      request.resolution = 320;
      window.exports()->startExport(request);
      say("exporting");
    } else {
      window.logBoard()->openRandomLog(7);
    }
  });
  QObject::connect(&window, &MainWindow::logOpened, [&] {
    if (mode == "save") {
      auto saveAgain = std::make_shared<std::function<void(int)>>();
      *saveAgain = [&window, ring, saveAgain](int n) {
        window.document()->editParameter(ring, {n % 2 ? 3.0f : 2.0f, 0, 0}, true);
        if (!window.save()) QCoreApplication::exit(4);
        say(qPrintable(QString("saved %1").arg(n)));
        QTimer::singleShot(0, [saveAgain, n] { (*saveAgain)(n + 1); });
      };
      (*saveAgain)(1);
    }
  });
  QObject::connect(&window, &MainWindow::ringsDetected, [&] {
    window.rings()->fitGrowthField();
    say("fitting");
  });
  QObject::connect(&window, &MainWindow::growthFieldFitted, [] { say("fitted"); });
  QObject::connect(&window, &MainWindow::exportFinished, [] { say("exported"); });
  QObject::connect(&window, &MainWindow::exportFailed, [](const QString& message) {
    std::fprintf(stderr, "crash_child: %s\n", qPrintable(message));
    QCoreApplication::exit(3);
  });
  window.openDocument(QString::fromLocal8Bit(argv[2]));
  return app.exec();
}
