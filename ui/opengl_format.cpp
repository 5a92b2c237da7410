#include "ui/opengl_format.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QSurfaceFormat>
#include <QtGlobal>
#include <algorithm>

namespace garment::ui {

void use_opengl_core_profile() {
  QSurfaceFormat format;
  format.setRenderableType(QSurfaceFormat::OpenGL);
  format.setVersion(3, 3);
  format.setProfile(QSurfaceFormat::CoreProfile);
  format.setDepthBufferSize(24);
  // 4× multisampling smooths the garment's edges on a GPU; the software rasteriser (Mesa's
  // llvmpipe, e.g. under Xvfb) pays for it several times over per frame, which would make live
  // updates slow there. GARMENT_STUDIO_SAMPLES overrides the sample count.
  bool set = false;
  const int samples = qEnvironmentVariableIntValue("GARMENT_STUDIO_SAMPLES", &set);
  format.setSamples(set ? std::max(0, samples) : 4);
  QSurfaceFormat::setDefaultFormat(format);
}

bool software_opengl() {
  static const bool software = [] {
    QOpenGLContext context;
    context.setFormat(QSurfaceFormat::defaultFormat());
    QOffscreenSurface surface;
    surface.setFormat(context.format());
    surface.create();
    if (!context.create() || !context.makeCurrent(&surface)) return false;
    const auto* renderer =
        reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
    const QString name = renderer ? QString::fromLatin1(renderer) : QString();
    context.doneCurrent();
    return name.contains("llvmpipe") || name.contains("softpipe") || name.contains("Software");
  }();
  return software;
}

void drop_multisampling_on_software_opengl() {
  if (qEnvironmentVariableIsSet("GARMENT_STUDIO_SAMPLES") || !software_opengl()) return;
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setSamples(0);
  QSurfaceFormat::setDefaultFormat(format);
}

}  // namespace garment::ui
