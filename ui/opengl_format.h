#pragma once
// The OpenGL context the avatar view needs (3.3 core, depth buffer, 4× multisampling; the view
// drops multisampling on a software rasteriser; GARMENT_STUDIO_SAMPLES=N overrides it), set as the
// default before the QApplication exists so that every context shares it.

namespace garment::ui {

void use_opengl_core_profile();

// Whether OpenGL here is a software rasteriser (Mesa's llvmpipe, e.g. under Xvfb). Needs the
// QGuiApplication; asked once, then remembered.
bool software_opengl();

// Called once the QApplication exists, before any window: on a software rasteriser, no
// multisampling by default (unless GARMENT_STUDIO_SAMPLES says), since the window's composition of
// the 3D view pays for it on every repaint of any widget (bench_studio: the studio's processor
// time against the command line's fell from 1.59× to 1.33× on the demo).
void drop_multisampling_on_software_opengl();

}  // namespace garment::ui
