#pragma once
// Files shipped in resources/ that the editor opens by itself.

#include <QString>

namespace garment::ui {

QString demo_pattern_path();

}  // namespace garment::ui
