#include "ui/bundled_resources.h"

#include "engine/body/default_body.h"

namespace garment::ui {

QString demo_pattern_path() {
  return QString::fromStdString((resource_directory() / "demo" / "demo_pattern.json").string());
}

}  // namespace garment::ui
