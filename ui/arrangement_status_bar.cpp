#include "ui/arrangement_status_bar.h"

#include <QLabel>
#include <QProgressBar>
#include <cmath>

namespace garment::ui {

namespace {

constexpr const char* kPassColour = "#2e7d32";
constexpr const char* kFailColour = "#c62828";

}  // namespace

ArrangementStatusBar::ArrangementStatusBar(QWidget* parent) : QStatusBar(parent) {
  phase_ = new QLabel(this);
  batch_ = new QLabel(this);
  iteration_ = new QLabel(this);
  elapsed_ = new QLabel(this);
  progress_ = new QProgressBar(this);
  progress_->setRange(0, 100);
  progress_->setMaximumWidth(220);
  progress_->setTextVisible(true);
  for (QLabel* label : {phase_, batch_, iteration_, elapsed_}) {
    label->setMinimumWidth(90);
    addPermanentWidget(label);
  }
  addPermanentWidget(progress_);
  // Right after the phase, so that "done" is never read without the verdict.
  quality_ = new QLabel(this);
  quality_->setObjectName("quality_status");
  insertPermanentWidget(1, quality_);
  setStatus({});
}

void ArrangementStatusBar::setStatus(const ArrangementStatus& status) {
  status_ = status;
  phase_->setText(phaseText());
  batch_->setText(batchText());
  iteration_->setText(iterationText());
  elapsed_->setText(elapsedText());
  if (status_.running && status_.progress < 0.0) {
    progress_->setRange(0, 0);  // busy indicator
  } else {
    progress_->setRange(0, 100);
    progress_->setValue(std::max(0, progressPercent()));
  }
  quality_->setVisible(status_.quality_failures.has_value());
  quality_->setText(qualityText());
  if (status_.quality_failures) {
    const bool ok = status_.quality_failures->isEmpty();
    // White on a saturated background: readable on light and dark styles alike.
    quality_->setStyleSheet(
        QString("QLabel { color: white; background-color: %1; padding: 1px 6px; }")
            .arg(QLatin1String(ok ? kPassColour : kFailColour)));
    quality_->setToolTip(ok ? tr("The garment passes every quality check")
                            : status_.quality_failures->join('\n'));
  }
}

QString ArrangementStatusBar::phaseText() const {
  return status_.phase.isEmpty() ? tr("no arrangement") : tr("phase: %1").arg(status_.phase);
}

QString ArrangementStatusBar::batchText() const {
  if (status_.batch <= 0) return tr("batch: –");
  if (status_.batch_count <= 0) return tr("batch %1").arg(status_.batch);
  return tr("batch %1 of %2").arg(status_.batch).arg(status_.batch_count);
}

QString ArrangementStatusBar::iterationText() const {
  return tr("iteration %1").arg(status_.iteration);
}

QString ArrangementStatusBar::elapsedText() const {
  const int tenths = static_cast<int>(std::lround(10.0 * std::max(0.0, status_.elapsed_seconds)));
  const int minutes = tenths / 600;
  const int seconds = (tenths / 10) % 60;
  return tr("%1:%2.%3").arg(minutes).arg(seconds, 2, 10, QChar('0')).arg(tenths % 10);
}

QString ArrangementStatusBar::qualityText() const {
  if (!status_.quality_failures) return {};
  const qsizetype failures = status_.quality_failures->size();
  if (failures == 0) return tr("quality: ok");
  if (failures == 1) return tr("quality: fails — 1 problem");
  return tr("quality: fails — %1 problems").arg(failures);
}

int ArrangementStatusBar::progressPercent() const {
  if (status_.progress < 0.0) return status_.running ? -1 : 0;
  return static_cast<int>(std::lround(100.0 * std::min(1.0, status_.progress)));
}

}  // namespace garment::ui
