#pragma once
// The manual seed panel (paper §5.1.2): what the classifier chose, the seed in use, and a button
// that seeds the arrangement with the pieces selected in the pattern view at the body location
// chosen in the location list. Plain text in, requests out: the controller does the rest.

#include <QString>
#include <QWidget>

class QLabel;
class QPushButton;

namespace garment::ui {

class ManualSeedPanel : public QWidget {
  Q_OBJECT
 public:
  explicit ManualSeedPanel(QWidget* parent = nullptr);

  void setAutomaticSeed(const QString& text);  // the classifier's choice and why
  void setSeedInUse(const QString& text);
  // The current choice; the seed button is enabled when both are given.
  void setChoice(const QStringList& pieces, const QString& location);

  QString automaticSeedText() const;
  QString seedInUseText() const;
  QPushButton* seedButton() const { return seed_button_; }
  QPushButton* automaticButton() const { return automatic_button_; }

 signals:
  void seedRequested();           // the chosen pieces at the chosen location, then run
  void automaticSeedRequested();  // back to the classifier's seed, then run

 protected:
  void resizeEvent(QResizeEvent* event) override;

 private:
  // Asks the dock for the height the wrapped texts need at the current width: the main window's
  // dock layout does not ask for it (no height-for-width), and squeezed them to one clipped line.
  void reserveTextHeight();

  QLabel* automatic_ = nullptr;
  QLabel* in_use_ = nullptr;
  QLabel* choice_ = nullptr;
  QPushButton* seed_button_ = nullptr;
  QPushButton* automatic_button_ = nullptr;
};

}  // namespace garment::ui
