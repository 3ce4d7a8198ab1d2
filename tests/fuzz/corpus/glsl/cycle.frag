#version 450
#include "lib/cycle.glsl"
