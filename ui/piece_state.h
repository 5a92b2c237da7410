#pragma once
// What the arrangement has done with each piece, as the editor shows it. The session maps its own
// per-piece state onto this; the views know nothing else about the session.

#include <QColor>
#include <QString>

namespace garment::ui {

enum class PieceState { Waiting, InBatch, Arranged, Seed };

QColor piece_state_colour(PieceState state);
QString piece_state_name(PieceState state);

}  // namespace garment::ui
