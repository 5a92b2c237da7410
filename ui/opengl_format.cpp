#include "ui/opengl_format.h"

#include <QSurfaceFormat>

namespace garment::ui {

void use_opengl_core_profile() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  format.setSamples(4);
  QSurfaceFormat::setDefaultFormat(format);
}

}  // namespace garment::ui
