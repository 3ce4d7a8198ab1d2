// Showing the renderer's frame in a window (the window uses the same render path as headless:
// it only copies the finished colour target to the default framebuffer).
#pragma once

#include "image/image.h"
#include "render/renderer.h"

namespace ps {

// Blits the renderer's width x height colour region to the default framebuffer (the window's
// back buffer), scaled to dst_w x dst_h with linear filtering. Restores the FBO bindings.
void present_to_default_framebuffer(const Renderer& renderer, int dst_w, int dst_h);

// glReadPixels(GL_BACK) of the default framebuffer before the swap (after the swap GL_FRONT
// reads black on llvmpipe/Xvfb): RGB, top row first, like Renderer::read_color().
Image read_back_buffer(int width, int height);

}  // namespace ps
