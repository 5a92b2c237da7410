#include "ui/piece_state.h"

#include <QObject>

namespace garment::ui {

QColor piece_state_colour(PieceState state) {
  switch (state) {
    case PieceState::Waiting:
      return QColor(200, 200, 196);
    case PieceState::InBatch:
      return QColor(242, 178, 64);
    case PieceState::Arranged:
      return QColor(122, 194, 122);
    case PieceState::Seed:
      return QColor(150, 128, 226);
  }
  return QColor(200, 200, 196);
}

QString piece_state_name(PieceState state) {
  switch (state) {
    case PieceState::Waiting:
      return QObject::tr("waiting");
    case PieceState::InBatch:
      return QObject::tr("in the current batch");
    case PieceState::Arranged:
      return QObject::tr("arranged");
    case PieceState::Seed:
      return QObject::tr("seed");
  }
  return {};
}

}  // namespace garment::ui
