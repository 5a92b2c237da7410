#include "ui/manual_seed_panel.h"

#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

namespace garment::ui {

ManualSeedPanel::ManualSeedPanel(QWidget* parent) : QWidget(parent) {
  setObjectName("manual_seed_panel");
  auto make_label = [this](const char* name) {
    auto* label = new QLabel(this);
    label->setObjectName(name);
    label->setWordWrap(true);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    return label;
  };
  automatic_ = make_label("automatic_seed");
  in_use_ = make_label("seed_in_use");
  choice_ = make_label("seed_choice");
  auto* form = new QFormLayout;
  form->addRow(tr("Classifier:"), automatic_);
  form->addRow(tr("In use:"), in_use_);
  form->addRow(tr("Chosen:"), choice_);

  seed_button_ = new QPushButton(tr("Seed here and run"), this);
  seed_button_->setObjectName("seed_button");
  seed_button_->setToolTip(
      tr("Arrange from the pieces selected in the pattern view, placed at the body location "
         "selected in the list"));
  automatic_button_ = new QPushButton(tr("Classifier's seed"), this);
  automatic_button_->setObjectName("automatic_seed_button");
  connect(seed_button_, &QPushButton::clicked, this, &ManualSeedPanel::seedRequested);
  connect(automatic_button_, &QPushButton::clicked, this, &ManualSeedPanel::automaticSeedRequested);
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(seed_button_);
  buttons->addWidget(automatic_button_);

  auto* layout = new QVBoxLayout(this);
  layout->addLayout(form);
  layout->addLayout(buttons);
  layout->addStretch(1);
  setChoice({}, {});
}

void ManualSeedPanel::setAutomaticSeed(const QString& text) {
  automatic_->setText(text);
  reserveTextHeight();
}

void ManualSeedPanel::setSeedInUse(const QString& text) {
  in_use_->setText(text);
  reserveTextHeight();
}

void ManualSeedPanel::setChoice(const QStringList& pieces, const QString& location) {
  const QString piece_text =
      pieces.isEmpty() ? tr("select pieces in the pattern view") : pieces.join(", ");
  const QString location_text =
      location.isEmpty() ? tr("choose a body location (list or marker)") : location;
  choice_->setText(tr("%1 → %2").arg(piece_text, location_text));
  seed_button_->setEnabled(!pieces.isEmpty() && !location.isEmpty());
  reserveTextHeight();
}

void ManualSeedPanel::resizeEvent(QResizeEvent* event) {
  QWidget::resizeEvent(event);
  reserveTextHeight();
}

void ManualSeedPanel::reserveTextHeight() {
  const int needed = layout()->heightForWidth(width());
  if (needed > 0 && needed != minimumHeight()) setMinimumHeight(needed);
}

QString ManualSeedPanel::automaticSeedText() const {
  return automatic_->text();
}

QString ManualSeedPanel::seedInUseText() const {
  return in_use_->text();
}

}  // namespace garment::ui
