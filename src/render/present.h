// Showing the renderer's frame in a window (the window uses the same render path as headless:
// it only copies the finished colour target to the default framebuffer).
#pragma once

#include "gl/objects.h"
#include "image/image.h"
#include "render/renderer.h"

namespace ps {

// Blits the renderer's width x height colour region to the default framebuffer (the window's
// back buffer), scaled to dst_w x dst_h with linear filtering (nearest at the same size). Works
// whatever scissor, sRGB or pixel-pack state the caller left, and restores every GL state it
// changes: framebuffer bindings, scissor and sRGB enables, pixel-pack buffer and parameters.
void present_to_default_framebuffer(const Renderer& renderer, int dst_w, int dst_h);
// The same into `target`'s draw buffer (headless tests, offscreen windows).
void present_to_framebuffer(const Renderer& renderer, const gl::Framebuffer& target, int dst_w, int dst_h);

// glReadPixels(GL_BACK) of the default framebuffer before the swap (after the swap GL_FRONT
// reads black on llvmpipe/Xvfb): RGB, top row first, like Renderer::read_color(). Restores the
// same state as present_to_default_framebuffer(), and the default framebuffer's read buffer.
Image read_back_buffer(int width, int height);

}  // namespace ps
