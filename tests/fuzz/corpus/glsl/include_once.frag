#version 450
#include "lib/a.glsl"
#include "lib/a.glsl"
void main(){}
