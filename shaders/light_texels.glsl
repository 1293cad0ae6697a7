// The light buffer's texels (layout in renderer/gpu/light_buffer.h): a buffer texture, or where
// buffer textures are missing (WebGL2: GBL_NO_BUFFER_TEXTURES) a 2D RGBA32F texture whose rows of
// GBL_LIGHT_TEXELS_PER_ROW texels hold them in order.
#ifdef GBL_NO_BUFFER_TEXTURES
uniform highp sampler2D uLights;
vec4 lightTexel(int i) { return texelFetch(uLights, ivec2(i % GBL_LIGHT_TEXELS_PER_ROW, i / GBL_LIGHT_TEXELS_PER_ROW), 0); }
int lightTexelCount() { ivec2 s = textureSize(uLights, 0); return s.x * s.y; }
#else
uniform samplerBuffer uLights;
vec4 lightTexel(int i) { return texelFetch(uLights, i); }
int lightTexelCount() { return textureSize(uLights); }
#endif
