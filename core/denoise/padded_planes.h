#pragma once
// A frame's channels as float planes with a border of `pad` pixels on every side that repeats
// the frame's edge, so that the filter's inner loops reach any neighbour within pad of a pixel by
// a fixed index offset, with no clamping, over contiguous floats.
#include <cstddef>
#include <vector>

namespace woven {

class PaddedPlanes {
public:
    PaddedPlanes() = default;
    // `channels` planes of width x height, the values given by value(pixel, channel) at each
    // pixel of the frame.
    template <typename F>
    PaddedPlanes(int width, int height, int channels, int pad, F&& value);

    int stride() const { return width_ + 2 * pad_; }
    // The padded index of frame pixel (x, y); x and y may be up to pad outside the frame.
    size_t index(int x, int y) const { return size_t(y + pad_) * size_t(stride()) + size_t(x + pad_); }
    const float* plane(int channel) const { return data_[size_t(channel)].data(); }
    int channels() const { return int(data_.size()); }

private:
    int width_ = 0, pad_ = 0;
    std::vector<std::vector<float>> data_;
};

template <typename F>
PaddedPlanes::PaddedPlanes(int width, int height, int channels, int pad, F&& value)
    : width_(width), pad_(pad), data_(size_t(channels)) {
    const size_t rows = size_t(height + 2 * pad);
    for (int c = 0; c < channels; ++c) {
        std::vector<float>& plane = data_[size_t(c)];
        plane.resize(rows * size_t(stride()));
        for (int y = -pad; y < height + pad; ++y) {
            const int sy = y < 0 ? 0 : (y >= height ? height - 1 : y);
            for (int x = -pad; x < width + pad; ++x) {
                const int sx = x < 0 ? 0 : (x >= width ? width - 1 : x);
                plane[index(x, y)] = value(size_t(sy) * size_t(width) + size_t(sx), c);
            }
        }
    }
}

}  // namespace woven
