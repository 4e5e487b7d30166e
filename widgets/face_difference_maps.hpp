#pragma once
// The faces view's difference heat maps (face_difference.hpp), computed on the background pool so the GUI
// thread never waits for them: six 1024 px faces take 130-200 ms on two cores
// (tests/widgets/test_faces_compare.cpp, differenceTiming). request() while a computation runs keeps only the
// newest inputs and starts them when it returns; ready() says that maps() holds the maps of the newest
// request.
#include <QFutureWatcher>
#include <QImage>
#include <QObject>
#include <array>
#include <optional>

namespace kerf {

class FaceDifferenceMaps : public QObject {
  Q_OBJECT

 public:
  using Faces = std::array<QImage, 6>;

  explicit FaceDifferenceMaps(QObject* parent = nullptr);

  void request(const Faces& photos, const Faces& models);
  // The last maps computed (possibly of older inputs while upToDate() is false); empty before the first.
  const Faces& maps() const { return maps_; }
  bool upToDate() const { return !computing_ && !pending_; }

 signals:
  void ready();

 private:
  void start(const Faces& photos, const Faces& models);
  void finished();

  QFutureWatcher<Faces> watcher_;
  std::optional<std::pair<Faces, Faces>> pending_;  // photos, models
  Faces maps_;
  bool computing_ = false;  // from start() until finished() has the result (not the future's own state)
};

}  // namespace kerf
