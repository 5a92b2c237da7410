#pragma once
// Pieces dragged from the pattern view onto a body location marker in the 3D view: the piece
// indices in a MIME type of the studio's own, so that nothing else (a file, text) is taken for
// them.

#include <QByteArray>
#include <QList>
#include <QMimeData>
#include <QStringList>

namespace garment::ui {

inline constexpr char kPieceMimeType[] = "application/x-garment-studio-pieces";

// A drag's data carrying these piece indices (the caller owns it, QDrag takes it).
inline QMimeData* piece_mime_data(const QList<int>& pieces) {
  QStringList indices;
  for (int piece : pieces)
    indices << QString::number(piece);
  auto* data = new QMimeData;
  data->setData(kPieceMimeType, indices.join(',').toUtf8());
  return data;
}

// The piece indices a drag carries; empty when it carries none.
inline QList<int> pieces_from_mime_data(const QMimeData* data) {
  QList<int> pieces;
  if (!data || !data->hasFormat(kPieceMimeType)) return pieces;
  for (const QString& index :
       QString::fromUtf8(data->data(kPieceMimeType)).split(',', Qt::SkipEmptyParts)) {
    bool ok = false;
    const int piece = index.toInt(&ok);
    if (ok && piece >= 0) pieces << piece;
  }
  return pieces;
}

}  // namespace garment::ui
