#pragma once
// The status bar of the editor: the arrangement's phase, batch, iteration, elapsed time and a
// progress bar, from plain values the session integration fills in; once the arrangement has ended,
// whether the garment passes its quality verdict, green or red, so that a failed garment never
// shows only "done".

#include <QStatusBar>
#include <QString>
#include <QStringList>
#include <optional>

class QLabel;
class QProgressBar;

namespace garment::ui {

struct ArrangementStatus {
  QString phase;        // "seed", "align", ...; empty: no session
  int batch = 0;        // 1-based; 0: none yet
  int batch_count = 0;  // 0: unknown
  int iteration = 0;    // within the current phase
  double elapsed_seconds = 0.0;
  double progress = -1.0;  // of the whole arrangement in [0, 1]; < 0 unknown (busy bar)
  bool running = false;    // false: the progress bar shows the last value, not a busy bar
  // Once the arrangement has ended: one line per failure of the garment's quality verdict (empty:
  // it passes); nullopt while it has not ended.
  std::optional<QStringList> quality_failures;
};

class ArrangementStatusBar : public QStatusBar {
  Q_OBJECT
 public:
  explicit ArrangementStatusBar(QWidget* parent = nullptr);

  void setStatus(const ArrangementStatus& status);
  const ArrangementStatus& status() const { return status_; }

  QString phaseText() const;
  QString batchText() const;
  QString iterationText() const;
  QString elapsedText() const;
  int progressPercent() const;  // -1 while busy (unknown progress)
  QString qualityText() const;  // empty while the arrangement has not ended
  QLabel* qualityLabel() const { return quality_; }

 private:
  ArrangementStatus status_;
  QLabel* phase_ = nullptr;
  QLabel* batch_ = nullptr;
  QLabel* iteration_ = nullptr;
  QLabel* elapsed_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* quality_ = nullptr;
};

}  // namespace garment::ui
