// Partial coverage without sorting: a fragment is kept where its opacity exceeds a threshold
// that varies over each 4 x 4 pixel block (woven's see-through gaps, glTF's BLEND alpha).
// The threshold in (0, 1) of this pixel, from a 4 x 4 ordered-dither (Bayer) matrix.
float ditherThreshold() {
    ivec2 q = ivec2(gl_FragCoord.xy) & 3;
    const int bayer[16] = int[](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
    return (float(bayer[q.y * 4 + q.x]) + 0.5) / 16.0;
}
