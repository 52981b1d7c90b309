/* SPDX-License-Identifier: Apache-2.0 */
/*
 * image_oiio.cpp - rtu image I/O through OpenImageIO (2.4 API), for every
 * format other than the built-in PPM and PFM of image.c.
 *
 * Compiled only when the library is built with OpenImageIO (RTU_HAVE_OIIO);
 * reached only through the hidden functions of image_internal.h, whose
 * contracts apply.  Conventions:
 *   - Memory holds rtReadPixels images: RGBA, rows bottom to top.  Image
 *     files hold rows top to bottom, so both directions walk memory with a
 *     negative scanline stride starting at the last row.
 *   - Alpha is straight (unassociated), as rtReadPixels returns it: a
 *     background pixel keeps the clear colour whatever the clear alpha.
 *     OpenImageIO assumes associated alpha unless told otherwise, which
 *     would divide colours by alpha on writing PNG and multiply on reading,
 *     so both directions set "oiio:UnassociatedAlpha".
 *   - No C++ exception crosses into C: every entry point catches all.
 */
#include "image_internal.h"

#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace {

// Largest accepted image, as in image.c (RTU_IMAGE_MAX_SIDE, RTU_IMAGE_MAX_PIXELS);
// tag-rtu-image-limits: keep the two in step.
const long max_side = 65536L;
const long max_pixels = 1L << 28;

void copy_error(char *error, size_t error_size, std::string message)
{
    while (!message.empty() && (message.back() == '\n' || message.back() == ' '))
        message.pop_back();
    if (message.empty())
        message = "OpenImageIO failed without a message";
    std::snprintf(error, error_size, "%s", message.c_str());
}

OIIO::TypeDesc component_type(int is_float)
{
    return is_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
}

size_t component_size(int is_float)
{
    return is_float ? sizeof(float) : 1;
}

int save(const char *path, int width, int height, int is_float, const void *pixels,
         char *error, size_t error_size)
{
    std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
    if (!out) {
        copy_error(error, error_size, OIIO::geterror());
        return 0;
    }
    const int channels = out->supports("alpha") ? 4 : 3;
    OIIO::ImageSpec spec(width, height, channels, component_type(is_float));
    spec.attribute("oiio:UnassociatedAlpha", 1);
    if (!out->open(path, spec)) {
        copy_error(error, error_size, out->geterror());
        return 0;
    }
    const OIIO::stride_t pixel_stride = (OIIO::stride_t)(4 * component_size(is_float));
    const OIIO::stride_t row_stride = pixel_stride * width;
    const unsigned char *top_row =
        static_cast<const unsigned char *>(pixels) + (size_t)row_stride * (size_t)(height - 1);
    bool ok = out->write_image(component_type(is_float), top_row, pixel_stride, -row_stride);
    std::string message = ok ? std::string() : out->geterror();
    if (!out->close() && ok) {
        ok = false;
        message = out->geterror();
    }
    if (!ok) {
        copy_error(error, error_size, message);
        std::remove(path); // do not leave a truncated file behind
        return 0;
    }
    return 1;
}

void *load(const char *path, int *width, int *height, int is_float, char *error,
           size_t error_size)
{
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
    if (!in) {
        copy_error(error, error_size, OIIO::geterror());
        return nullptr;
    }
    const OIIO::ImageSpec &spec = in->spec();
    const long w = spec.width;
    const long h = spec.height;
    if (spec.deep || spec.depth != 1 || spec.nchannels < 1) {
        copy_error(error, error_size, "deep, volume or channel-less images are not supported");
        return nullptr;
    }
    if (w < 1 || h < 1 || w > max_side || h > max_side || w > max_pixels / h) {
        // snprintf rather than std::to_string, whose digit table libstdc++
        // exports as a unique global symbol from our library.
        std::snprintf(error, error_size, "image size %ld x %ld is empty or larger than supported",
                      w, h);
        return nullptr;
    }
    const int channels = spec.nchannels < 4 ? spec.nchannels : 4;
    const size_t size = component_size(is_float);
    const size_t pixel_count = (size_t)w * (size_t)h;
    std::vector<unsigned char> file_pixels(pixel_count * (size_t)channels * size);
    const OIIO::stride_t row_stride = (OIIO::stride_t)((size_t)w * (size_t)channels * size);
    // Start at the last memory row and step backwards: file row 0 is the top.
    if (!in->read_image(0, 0, 0, channels, component_type(is_float),
                        file_pixels.data() + (size_t)row_stride * (size_t)(h - 1),
                        OIIO::AutoStride, -row_stride)) {
        copy_error(error, error_size, in->geterror());
        return nullptr;
    }
    in->close();

    unsigned char *rgba = static_cast<unsigned char *>(std::malloc(pixel_count * 4 * size));
    if (rgba == nullptr) {
        copy_error(error, error_size, "out of memory");
        return nullptr;
    }
    // Channel c of the RGBA result comes from file channel map[channels-1][c];
    // -1 means opaque alpha.
    static const int map[4][4] = {{0, 0, 0, -1}, {0, 0, 0, 1}, {0, 1, 2, -1}, {0, 1, 2, 3}};
    const int *from = map[channels - 1];
    for (size_t i = 0; i < pixel_count; i++) {
        for (int c = 0; c < 4; c++) {
            const size_t dst = (i * 4 + (size_t)c) * size;
            if (from[c] < 0) {
                if (is_float) {
                    const float one = 1.0f;
                    std::memcpy(rgba + dst, &one, sizeof one);
                } else {
                    rgba[dst] = 255;
                }
            } else {
                std::memcpy(rgba + dst,
                            file_pixels.data() + (i * (size_t)channels + (size_t)from[c]) * size,
                            size);
            }
        }
    }
    *width = (int)w;
    *height = (int)h;
    return rgba;
}

} // namespace

extern "C" int rtu_oiio_save(const char *path, int width, int height, int is_float,
                             const void *pixels, char *error, size_t error_size)
{
    try {
        return save(path, width, height, is_float, pixels, error, error_size);
    } catch (const std::exception &e) {
        copy_error(error, error_size, std::string("OpenImageIO: ") + e.what());
    } catch (...) {
        copy_error(error, error_size, "OpenImageIO: unknown exception");
    }
    return 0;
}

extern "C" void *rtu_oiio_load(const char *path, int *width, int *height, int is_float,
                               char *error, size_t error_size)
{
    try {
        return load(path, width, height, is_float, error, error_size);
    } catch (const std::exception &e) {
        copy_error(error, error_size, std::string("OpenImageIO: ") + e.what());
    } catch (...) {
        copy_error(error, error_size, "OpenImageIO: unknown exception");
    }
    return nullptr;
}

extern "C" int rtu_oiio_can_write(const char *extension)
{
    try {
        std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(extension);
        if (!out) {
            OIIO::geterror(); // clear the "no plugin" message OpenImageIO keeps per thread
            return 0;
        }
        return 1;
    } catch (...) {
        return 0;
    }
}
