#pragma once
// Files shipped in resources/ that the editor opens by itself (the default body is the engine's
// default_body_path()).

#include <QString>

namespace garment::ui {

QString demo_pattern_path();

}  // namespace garment::ui
