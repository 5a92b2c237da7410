#include "ui/garment_diagnostics_worker.h"

#include <exception>

namespace garment::ui {

struct GarmentDiagnosticsWorker::Checker {
  std::shared_ptr<const Garment> garment;
  std::unique_ptr<BodyReference> body;
  std::unique_ptr<GarmentChecker> checker;
};

GarmentDiagnosticsWorker::GarmentDiagnosticsWorker(QObject* parent) : QObject(parent) {}

GarmentDiagnosticsWorker::~GarmentDiagnosticsWorker() {
  if (running_.valid()) running_.wait();
}

void GarmentDiagnosticsWorker::setScene(std::shared_ptr<const Garment> garment,
                                        std::shared_ptr<const BodyMesh> body) {
  garment_ = std::move(garment);
  body_ = std::move(body);
  ++scene_;
  pending_.reset();
  // A running measurement keeps its own reference to the old checker.
  checker_ = std::make_shared<Checker>();
}

void GarmentDiagnosticsWorker::measure(std::shared_ptr<const Eigen::MatrixX3d> positions) {
  if (!garment_ || !positions || positions->rows() != garment_->vertex_count()) return;
  if (running_.valid())
    pending_ = std::move(positions);
  else
    start(std::move(positions));
}

void GarmentDiagnosticsWorker::start(std::shared_ptr<const Eigen::MatrixX3d> positions) {
  running_ = std::async(std::launch::async, [this, checker = checker_, garment = garment_,
                                             body = body_, positions = std::move(positions),
                                             scene = scene_] {
    std::shared_ptr<GarmentDiagnostics> diagnostics;
    try {
      if (!checker->checker) {
        checker->garment = garment;
        if (body) checker->body = std::make_unique<BodyReference>(*body);
        checker->checker = std::make_unique<GarmentChecker>(*garment, checker->body.get(),
                                                            expected_regions_from_names(*garment));
      }
      diagnostics = std::make_shared<GarmentDiagnostics>();
      checker->checker->measure(*positions, diagnostics.get());
    } catch (const std::exception& error) {
      qWarning("garment diagnostics: %s", error.what());
      diagnostics.reset();
    }
    // Delivered on the GUI thread; the destructor waits for this task, so `this` is alive here,
    // and Qt drops the queued call if the object is gone by the time it would run.
    QMetaObject::invokeMethod(
        this, [this, diagnostics, scene] { finished(diagnostics, scene); }, Qt::QueuedConnection);
  });
}

void GarmentDiagnosticsWorker::finished(std::shared_ptr<const GarmentDiagnostics> diagnostics,
                                        int scene) {
  if (running_.valid()) running_.get();
  if (scene == scene_) Q_EMIT diagnosticsReady(std::move(diagnostics));
  if (pending_) start(std::move(pending_));
}

}  // namespace garment::ui
