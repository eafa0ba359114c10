#pragma once
// A rendered frame's files: OpenEXR with the linear radiance, its render passes, the per-pixel
// sample counts and what `woven merge` needs to merge renders of disjoint sample ranges exactly
// (exact sums, the sample range, the frame's identity), or a display-ready PNG. Every failure throws ImageError
// naming the file; every write is atomic (atomic_file.h).
#include <optional>
#include <string>
#include <vector>

#include "display_transform.h"
#include "exact_sum.h"
#include "frame_identity.h"
#include "image_io.h"
#include "render_passes.h"
#include "sample_range.h"

namespace woven {

// A linear image with, optionally, how many samples each pixel's value is the mean of, and what
// a render keeps so that renders of disjoint sample ranges merge exactly: the exact sums of the
// samples, which samples they are and which frame they are samples of.
struct ExrImage {
    Image image;
    std::vector<float> sampleCount;        // empty, or one per pixel (channel "N")
    std::vector<ExactSum> sampleSums{};    // empty, or three per pixel: R, G, B
    std::optional<SampleRange> samples{};  // the same for every pixel
    std::optional<FrameIdentity> frame{};  // none in files of other tools and of woven before it
    std::vector<PassSums> passSums{};      // empty, or one per pixel: the render passes' exact sums
    std::optional<Image> noisy{};          // where `image` is denoised, the noisy beauty it was made from
    // passSums' direct-light sums are 0: the file is of a woven before that pass (2026-12-04).
    bool lacksDirectPass = false;

    RenderPasses passes() const { return meanPasses(image.width, image.height, sampleCount, sampleSums, passSums); }
};
enum class ExrPrecision { Half, Float };

// Writes one RLE-compressed part whose channels are all half or float, named R, G, B or
// layer.pass.channel as compositors read layers (Blender 3.4 loads no file with other types or
// names: tests/app/exr_readers_test.cpp):
//   R, G, B            the beauty (`image`, in `precision`), denoised where `noisy` is set;
//   noisy.R/G/B        the noisy beauty, when set (`precision`);
//   albedo.R/G/B, normal.X/Y/Z, depth.Z, variance.R/G/B, direct.R/G/B
//                      the render passes (RenderPasses, `precision`), when passSums is not empty;
//   samples.N          the sample counts, when not empty (float, exact for counts below 2^24);
//   exact.radianceK.R/G/B, exact.albedoK.R/G/B, exact.normalK.X/Y/Z, exact.depthK.Z,
//   exact.squareK.R/G/B, exact.directK.R/G/B, exact.directSquareK.Y (K = 0..5; files of
//   versions before the direct pass lack exact.direct* and are read with it 0)
//                      the exact sums, each as ExactSum::floatWords() (whole numbers below 2^24,
//                      float), K = 0 the least significant: the radiance's with sampleSums,
//                      the passes' with passSums. Blender shows them as a second layer, "exact".
// The sample range goes to attributes wovenFirstSample and wovenSampleCount (decimal strings: EXR
// has no 64-bit integer attribute; files of earlier versions have ints, which are read too), the
// frame's identity to wovenScene, wovenSeed (strings), wovenIntegrator (a string), wovenMaxDepth
// and wovenFilter (ints). readExr also reads the layout before render passes: the count as N and
// the radiance's sums as 32-bit unsigned channels sum.R0-sum.B3 (ExactSum::words()).
void writeExr(const std::string& path, const ExrImage& exr,
              ExrPrecision precision = ExrPrecision::Half);
ExrImage readExr(const std::string& path);

// ".exr" for "out/Frame.EXR": the extension with its dot, in lower case; "" for none.
std::string lowerExtension(const std::string& path);

// A rendered frame, by its file's extension (either case): .exr keeps the linear radiance in
// 32-bit floats and the sample counts; .png is display-transformed. Others throw ImageError.
void writeFrame(const std::string& path, const ExrImage& frame, const DisplayTransform& png);
// Throws the ImageError writeFrame would for `path`'s extension, or the FileWriteError of an
// output it may not be (checkOutput(), output_path.h): check before a long render.
void checkFrameFileName(const std::string& path);

}  // namespace woven
