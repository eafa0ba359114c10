// One frame of the preview's progressive refinement into the running mean: drawn with constant
// blending (alpha 1 / (frames + 1)), so mean' = mean + (frame - mean) / (frames + 1).
uniform sampler2D frame;

out vec4 mean;

void main() { mean = vec4(texelFetch(frame, ivec2(gl_FragCoord.xy), 0).rgb, 1.0); }
