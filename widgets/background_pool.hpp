#pragma once
// The thread pool for Kerf's own short background work outside the job runner (reading photos in the
// import dialog, writing the autosave copy). Never QThreadPool::globalInstance(): Qt 6.4 draws scaled
// images (QPainter::drawImage) with helper tasks on the global pool and waits for them on the GUI thread,
// so work of ours queued there stalled every repaint of the faces view until it finished (measured: the
// event loop stood still for 0.8 s while six 12-megapixel photos loaded; app.responsiveness).
#include <QThreadPool>

namespace kerf {

QThreadPool* backgroundPool();

}  // namespace kerf
