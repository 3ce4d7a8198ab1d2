#version 450
#include "lib/missing.glsl"
