#include "gltf_accessor.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace woven {

namespace {

int componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

template <typename T>
T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));  // buffer views need not be aligned for T
    return value;
}

double readComponent(const unsigned char* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            const double v = load<int8_t>(p);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            const double v = load<uint8_t>(p);
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            const double v = load<int16_t>(p);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            const double v = load<uint16_t>(p);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load<uint32_t>(p);
        default: return load<float>(p);
    }
}

// The bytes of buffer view `viewIndex` from `offset` on, checked to hold `count` elements of
// `elementSize` bytes, `stride` apart.
const unsigned char* viewBytes(const tinygltf::Model& model, int viewIndex, size_t offset, size_t count,
                               size_t elementSize, size_t stride, const std::string& what) {
    if (viewIndex < 0 || size_t(viewIndex) >= model.bufferViews.size())
        throw AccessorError(what + ": buffer view " + std::to_string(viewIndex) + " does not exist");
    const tinygltf::BufferView& view = model.bufferViews[viewIndex];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        throw AccessorError(what + ": buffer view " + std::to_string(viewIndex) + " names buffer " +
                            std::to_string(view.buffer) + ", which does not exist");
    const tinygltf::Buffer& buffer = model.buffers[view.buffer];
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
        throw AccessorError(what + ": buffer view " + std::to_string(viewIndex) + " (bytes " +
                            std::to_string(view.byteOffset) + " + " + std::to_string(view.byteLength) +
                            ") runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                            std::to_string(buffer.data.size()) + " bytes)");
    // In long double: a count from the file may make the product overflow size_t.
    const long double needed = count == 0 ? 0.0L : (long double)offset + (long double)(count - 1) * stride + elementSize;
    if (needed > (long double)view.byteLength)
        throw AccessorError(what + ": needs " + std::to_string((unsigned long long)std::min(needed, 1e19L)) + " bytes of buffer view " +
                            std::to_string(viewIndex) + ", which has " + std::to_string(view.byteLength));
    return buffer.data.data() + view.byteOffset + offset;
}

}  // namespace

AccessorData readAccessor(const tinygltf::Model& model, int accessorIndex) {
    const std::string what = "accessor " + std::to_string(accessorIndex);
    if (accessorIndex < 0 || size_t(accessorIndex) >= model.accessors.size())
        throw AccessorError(what + " does not exist");
    const tinygltf::Accessor& accessor = model.accessors[accessorIndex];
    const int size = componentSize(accessor.componentType);
    const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type));
    if (size == 0 || components <= 0 || components > 16)
        throw AccessorError(what + ": unsupported component type " + std::to_string(accessor.componentType) +
                            " or element type " + std::to_string(accessor.type));
    // Matrices are stored column by column, each column padded to a multiple of 4 bytes
    // (glTF 2.0, 3.6.2.4: MAT2 of bytes, MAT3 of bytes and shorts); vectors are one column.
    const bool matrix = accessor.type == TINYGLTF_TYPE_MAT2 || accessor.type == TINYGLTF_TYPE_MAT3 ||
                        accessor.type == TINYGLTF_TYPE_MAT4;
    const int rows = matrix ? (accessor.type == TINYGLTF_TYPE_MAT2 ? 2 : accessor.type == TINYGLTF_TYPE_MAT3 ? 3 : 4)
                            : components;
    const size_t columnBytes = matrix ? (size_t(rows * size) + 3) / 4 * 4 : size_t(rows * size);
    const auto componentOffset = [&](int c) { return size_t(c / rows) * columnBytes + size_t(c % rows) * size; };

    AccessorData data;
    data.components = components;
    data.count = accessor.count;
    const size_t elementSize = columnBytes * size_t(components / rows);
    // What the file claims is checked against what it holds before anything is allocated: an
    // accessor with a view must fit in it; one without (zeros, perhaps made sparse) can claim
    // no more elements than the file has bytes of buffers, as every real accessor needs some.
    size_t bufferBytes = 0;
    for (const tinygltf::Buffer& buffer : model.buffers) bufferBytes += buffer.data.size();
    if (accessor.bufferView >= 0) {
        if (size_t(accessor.bufferView) >= model.bufferViews.size())
            throw AccessorError(what + ": buffer view " + std::to_string(accessor.bufferView) + " does not exist");
        const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
        const size_t stride = view.byteStride ? view.byteStride : elementSize;
        viewBytes(model, accessor.bufferView, accessor.byteOffset, data.count, elementSize, std::max(stride, elementSize), what);
    } else if (data.count > std::max<size_t>(bufferBytes, 1)) {
        throw AccessorError(what + ": claims " + std::to_string(data.count) + " elements with no data behind them");
    }
    data.values.assign(data.count * components, 0.0);  // an accessor without a view reads zeros

    if (accessor.bufferView >= 0) {
        if (size_t(accessor.bufferView) >= model.bufferViews.size())
            throw AccessorError(what + ": buffer view " + std::to_string(accessor.bufferView) + " does not exist");
        const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
        const size_t stride = view.byteStride ? view.byteStride : elementSize;
        if (stride < elementSize)
            throw AccessorError(what + ": byte stride " + std::to_string(stride) + " is smaller than an element");
        const unsigned char* bytes = viewBytes(model, accessor.bufferView, accessor.byteOffset, data.count,
                                               elementSize, stride, what);
        for (size_t e = 0; e < data.count; ++e)
            for (int c = 0; c < components; ++c)
                data.values[e * components + c] =
                    readComponent(bytes + e * stride + componentOffset(c), accessor.componentType, accessor.normalized);
    }

    if (accessor.sparse.isSparse) {
        const auto& sparse = accessor.sparse;
        const size_t count = size_t(std::max(sparse.count, 0));
        const int indexSize = componentSize(sparse.indices.componentType);
        if (indexSize == 0 || sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT)
            throw AccessorError(what + ": sparse indices must be unsigned integers");
        const unsigned char* indices = viewBytes(model, sparse.indices.bufferView, sparse.indices.byteOffset,
                                                 count, indexSize, indexSize, what + " (sparse indices)");
        const unsigned char* values = viewBytes(model, sparse.values.bufferView, sparse.values.byteOffset,
                                                count, elementSize, elementSize, what + " (sparse values)");
        for (size_t s = 0; s < count; ++s) {
            const size_t target = size_t(readComponent(indices + s * indexSize, sparse.indices.componentType, false));
            if (target >= data.count)
                throw AccessorError(what + ": sparse index " + std::to_string(target) + " is out of range (count " +
                                    std::to_string(data.count) + ")");
            for (int c = 0; c < components; ++c)
                data.values[target * components + c] =
                    readComponent(values + s * elementSize + componentOffset(c), accessor.componentType, accessor.normalized);
        }
    }
    return data;
}

}  // namespace woven
