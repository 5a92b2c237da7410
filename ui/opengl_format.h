#pragma once
// The OpenGL context the avatar view needs (3.3 core, depth buffer, 4× multisampling; the view
// drops multisampling on a software rasteriser; GARMENT_STUDIO_SAMPLES=N overrides it), set as the
// default before the QApplication exists so that every context shares it.

namespace garment::ui {

void use_opengl_core_profile();

}  // namespace garment::ui
