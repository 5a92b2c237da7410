#pragma once
// Measures garment states off the GUI thread for the avatar view's overlays: the quality checker's
// per-element diagnostics (engine/quality/garment_metrics.h) of the latest positions it was given.
// At most one measurement runs at a time; positions given meanwhile replace each other, and only
// the last of them is measured next, so that live snapshots never pile up.
//
// Threads: call everything on the GUI thread; diagnosticsReady arrives there too. The destructor
// waits for a running measurement (a fraction of a second on the studio's garments).

#include <QObject>
#include <future>
#include <memory>

#include "engine/body/body_mesh.h"
#include "engine/pattern/garment_mesh.h"
#include "engine/quality/garment_metrics.h"

namespace garment::ui {

class GarmentDiagnosticsWorker : public QObject {
  Q_OBJECT
 public:
  explicit GarmentDiagnosticsWorker(QObject* parent = nullptr);
  ~GarmentDiagnosticsWorker() override;

  // The garment and the body (may be null: no body diagnostics) states are measured against; a
  // change drops a pending request, and results of a running one for the old scene are dropped.
  void setScene(std::shared_ptr<const Garment> garment, std::shared_ptr<const BodyMesh> body);
  // Asks for the diagnostics of #V by 3 positions; ignored without a garment or when the row count
  // is not the garment's vertex count.
  void measure(std::shared_ptr<const Eigen::MatrixX3d> positions);
  bool busy() const { return running_.valid(); }

 signals:
  // The diagnostics of the latest positions measured (null when the measurement failed, e.g. on
  // positions that are not finite, or a body that is not closed).
  void diagnosticsReady(std::shared_ptr<const garment::GarmentDiagnostics> diagnostics);

 private:
  // The checker and what it refers to, built by the first measurement of a scene (on the worker:
  // the body's search tree takes a moment) and reused by the next ones of that scene.
  struct Checker;

  void start(std::shared_ptr<const Eigen::MatrixX3d> positions);
  void finished(std::shared_ptr<const GarmentDiagnostics> diagnostics, int scene);

  std::shared_ptr<const Garment> garment_;
  std::shared_ptr<const BodyMesh> body_;
  std::shared_ptr<Checker> checker_;
  int scene_ = 0;  // counts setScene calls, to tell results of an old scene
  std::future<void> running_;
  std::shared_ptr<const Eigen::MatrixX3d> pending_;
};

}  // namespace garment::ui
