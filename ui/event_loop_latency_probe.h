#pragma once
// Measures how late the GUI event loop serves a periodic timer: a responsive window serves it
// within a few milliseconds; a blocked one late by as long as it was blocked. The editor's tests
// and benchmarks use it to show that the window stays responsive while the arrangement runs.

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>
#include <vector>

namespace garment::ui {

class EventLoopLatencyProbe : public QObject {
  Q_OBJECT
 public:
  explicit EventLoopLatencyProbe(int period_ms = 10, QObject* parent = nullptr);

  void start();  // clears earlier samples
  void stop();

  int sampleCount() const { return static_cast<int>(delays_ms_.size()); }
  // How late each tick came (milliseconds past its period), in arrival order.
  const std::vector<double>& delaysMs() const { return delays_ms_; }
  double maxDelayMs() const;
  double percentileDelayMs(double fraction) const;  // fraction in [0, 1]; 0 without samples

 private:
  void tick();

  int period_ms_;
  QTimer timer_;
  QElapsedTimer clock_;
  qint64 last_tick_ns_ = 0;
  std::vector<double> delays_ms_;
};

}  // namespace garment::ui
