#version 450 core
// Probe depth pass, mesh variant: writes the interpolated plane height (R32F).
layout(location = 0) in float v_height;
layout(location = 0) out float o_height;

void main() { o_height = v_height; }
