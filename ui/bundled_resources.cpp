#include "ui/bundled_resources.h"

namespace garment::ui {

QString demo_pattern_path() {
  return QString::fromUtf8(GARMENT_RESOURCE_DIR) + "/demo/demo_pattern.json";
}

}  // namespace garment::ui
