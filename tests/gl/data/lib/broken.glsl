// Deliberately broken include: the error must be reported at lib/broken.glsl:5.
#pragma once

float broken_value() {
  return undefined_thing * 2.0;
}
