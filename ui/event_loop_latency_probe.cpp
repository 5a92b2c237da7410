#include "ui/event_loop_latency_probe.h"

#include <algorithm>
#include <cmath>

namespace garment::ui {

EventLoopLatencyProbe::EventLoopLatencyProbe(int period_ms, QObject* parent)
    : QObject(parent), period_ms_(std::max(1, period_ms)) {
  timer_.setTimerType(Qt::PreciseTimer);
  timer_.setInterval(period_ms_);
  connect(&timer_, &QTimer::timeout, this, &EventLoopLatencyProbe::tick);
}

void EventLoopLatencyProbe::start() {
  delays_ms_.clear();
  clock_.start();
  last_tick_ns_ = 0;
  timer_.start();
}

void EventLoopLatencyProbe::stop() {
  timer_.stop();
}

void EventLoopLatencyProbe::tick() {
  const qint64 now_ns = clock_.nsecsElapsed();
  const double interval_ms = 1e-6 * static_cast<double>(now_ns - last_tick_ns_);
  last_tick_ns_ = now_ns;
  delays_ms_.push_back(std::max(0.0, interval_ms - period_ms_));
}

double EventLoopLatencyProbe::maxDelayMs() const {
  return delays_ms_.empty() ? 0.0 : *std::max_element(delays_ms_.begin(), delays_ms_.end());
}

double EventLoopLatencyProbe::percentileDelayMs(double fraction) const {
  if (delays_ms_.empty()) return 0.0;
  std::vector<double> sorted = delays_ms_;
  std::sort(sorted.begin(), sorted.end());
  const double clamped = std::clamp(fraction, 0.0, 1.0);
  const auto index = static_cast<std::size_t>(std::lround(clamped * (sorted.size() - 1)));
  return sorted[index];
}

}  // namespace garment::ui
