// The display's tonemap: HDR radiance times the exposure, squeezed into 0..1 by the chosen curve,
// then gamma-encoded for the RGBA8 display image. view.frag tonemaps the lit image with it, and
// the overlays drawn on the display afterwards (light_cube.frag, light_volume_wire.frag) tonemap
// their HDR colour with it too, so a cube looks exactly as it did when it was drawn into the lit
// image. Needs view_constants.glsl (TONEMAP_*) included first.
uniform int uTonemap;     // gbl::Tonemap
uniform float uExposure;

vec3 tonemap(vec3 hdr) {
    vec3 c = hdr * uExposure;
    if (uTonemap == TONEMAP_EXPOSURE) c = vec3(1.0) - exp(-c);
    else if (uTonemap == TONEMAP_REINHARD) c = c / (vec3(1.0) + c);
    else c = clamp(c, 0.0, 1.0);
    return pow(c, vec3(1.0 / 2.2));
}
