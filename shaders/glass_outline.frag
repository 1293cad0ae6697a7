// The glass outline overlay: where a blended surface is, diagonal magenta hatching over the view
// (the surface's own colour and light are the forward pass's; this only says where it is).
#version 330 core
out vec4 fragColor;

void main() {
    if (mod(gl_FragCoord.x + gl_FragCoord.y, 6.0) >= 2.0) discard;  // two pixels in six: the view shows between
    fragColor = vec4(1.0, 0.0, 1.0, 1.0);
}
