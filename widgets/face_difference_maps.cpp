#include "face_difference_maps.hpp"

#include <QtConcurrent>

#include "background_pool.hpp"
#include "face_difference.hpp"

namespace kerf {

FaceDifferenceMaps::FaceDifferenceMaps(QObject* parent) : QObject(parent) {
  connect(&watcher_, &QFutureWatcher<Faces>::finished, this, &FaceDifferenceMaps::finished);
}

void FaceDifferenceMaps::request(const Faces& photos, const Faces& models) {
  if (computing_) {
    pending_ = std::make_pair(photos, models);  // QImage copies share their pixels: cheap
    return;
  }
  start(photos, models);
}

void FaceDifferenceMaps::start(const Faces& photos, const Faces& models) {
  computing_ = true;
  // The work holds its own copies: it needs nothing of this object, which may be gone when it returns.
  watcher_.setFuture(
      QtConcurrent::run(backgroundPool(), [photos, models] { return differenceHeatMaps(photos, models); }));
}

void FaceDifferenceMaps::finished() {
  computing_ = false;
  maps_ = watcher_.result();  // kept even when stale: better than nothing until the newer ones come
  if (pending_) {
    const auto [photos, models] = std::move(*pending_);
    pending_.reset();
    start(photos, models);
    return;
  }
  emit ready();
}

}  // namespace kerf
