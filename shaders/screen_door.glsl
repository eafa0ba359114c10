// Partial coverage without sorting: a fragment is kept where its opacity exceeds a threshold
// that varies over each 4 x 4 pixel block (woven's see-through gaps, glTF's BLEND alpha) and,
// through the progressive refinement's frames, by ninths (view_refinement.h), so a resting view
// keeps each pixel's coverage to a ninth, not by the 4 x 4 block's sixteenths alone.
uniform int refinementFrame;  // 0 to kRefinementFrames - 1; 0 for a frame of its own

// The threshold in (0, 1) of this pixel, from a 4 x 4 ordered-dither (Bayer) matrix.
float ditherThreshold() {
    ivec2 q = ivec2(gl_FragCoord.xy) & 3;
    const int bayer[16] = int[](0, 8, 2, 10, 12, 4, 14, 6, 3, 11, 1, 9, 15, 7, 13, 5);
    return fract((float(bayer[q.y * 4 + q.x]) + 0.5) / 16.0 + float(refinementFrame) / 9.0);
}
