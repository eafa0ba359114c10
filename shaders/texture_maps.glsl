// The glTF textures a surface shader samples: maps[] holds them in the order of the MAP_<NAME>
// indices the C++ side defines with MAP_COUNT (GpuTextures::bindMaps).
#if MAP_COUNT > 0
// One texture use as core's TextureSampler: its set of texture coordinates and its
// KHR_texture_transform; sRGB decoding and wrap modes are the GL texture's and sampler's.
uniform sampler2D maps[MAP_COUNT];
uniform int mapTexCoord[MAP_COUNT];
uniform mat3 mapTransform[MAP_COUNT];

vec4 lookup(int i) {
    vec2 uv = mapTexCoord[i] == 1 ? vUv1 : vUv;
    return texture(maps[i], (mapTransform[i] * vec3(uv, 1.0)).xy);
}
#endif
