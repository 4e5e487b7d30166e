#include "background_pool.hpp"

#include <QThread>
#include <algorithm>

namespace kerf {

QThreadPool* backgroundPool() {
  static QThreadPool* pool = [] {
    auto* p = new QThreadPool;  // lives as long as the process: tasks may still run at exit
    p->setMaxThreadCount(std::max(1, QThread::idealThreadCount()));
    p->setObjectName("kerf-background");
    return p;
  }();
  return pool;
}

}  // namespace kerf
