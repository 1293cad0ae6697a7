// Stencil marking pass of the two-pass light volume: only depth and stencil matter.
#version 330 core
void main() {}
