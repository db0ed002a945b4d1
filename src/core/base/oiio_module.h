#pragma once
// OpenImageIO behind a module. Debian's libOpenImageIO pulls in ~260 shared
// libraries (FFmpeg, OpenCV, GDAL, ...) linked BIND_NOW: 0.35-0.5 s of
// dynamic loading before main(). So nothing of ours links it; what needs it
// (EXR, HDR, JPEG, TIFF, 16-bit PNG, GIF, the text of charts and sheets)
// calls this interface, implemented by libshadelab_oiio.so (src/core/oiio),
// which oiioModule() loads with dlopen on first use. 8-bit PNG, the default
// path, goes through libpng (png_codec.h) and never loads it.
//
// The interface mirrors the OpenImageIO calls its users made before, one for
// one, so images stay bit-identical. Nothing throws across it: failures return
// false with OpenImageIO's message.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace shadelab::oiio {

// Bumped whenever the classes below change: a stale module is refused.
inline constexpr uint32_t kInterfaceVersion = 1;

enum class PixelType : uint32_t { UInt8, UInt16, Half, Float, Double, Other };

struct ImageHeader {
  int width = 0;
  int height = 0;
  int channels = 0;
  PixelType stored = PixelType::Other;  // as in the file (OpenImageIO's nativespec)
};

// One image file (an OIIO::ImageBuf).
class ImageFile {
 public:
  virtual ~ImageFile() = default;
  // ImageBuf::init_spec: the header only.
  virtual bool readHeader(ImageHeader& header, std::string& error) = 0;
  // ImageBuf::read(subimage, 0, force, as); then header() is the buffer's.
  virtual bool read(int subimage, PixelType as, std::string& error) = 0;
  virtual ImageHeader header() const = 0;
  // ImageBuf::get_pixels of rows [yBegin, yEnd), every channel, as `as`.
  virtual void getRows(int yBegin, int yEnd, PixelType as, void* out) const = 0;
};

struct TextBox {  // OIIO::ROI of text_size: the box relative to the origin
  int xBegin = 0, xEnd = 0, yBegin = 0, yEnd = 0;
};
enum class AlignX : int { Left, Right, Center };            // ImageBufAlgo::TextAlignX
enum class AlignY : int { Baseline, Top, Bottom, Center };  // ImageBufAlgo::TextAlignY
struct Clip {                                               // a ROI over x and y, all four channels
  int xBegin, xEnd, yBegin, yEnd;
  bool contains(int x, int y) const { return x >= xBegin && x < xEnd && y >= yBegin && y < yEnd; }
};

// An RGBA drawing surface (an OIIO::ImageBuf) for charts and sheets.
class Canvas {
 public:
  virtual ~Canvas() = default;
  virtual int width() const = 0;
  virtual int height() const = 0;
  virtual void fill(const float color[4]) = 0;
  virtual void setPixel(int x, int y, const float color[4]) = 0;
  // ImageBufAlgo::render_line; no clip: the default ROI.
  virtual void line(int x0, int y0, int x1, int y1, const float color[4],
                    std::optional<Clip> clip) = 0;
  virtual void box(int x0, int y0, int x1, int y1, const float color[4]) = 0;
  virtual bool text(int x, int y, const std::string& text, int size, const std::string& font,
                    const float color[4], AlignX alignX, AlignY alignY, std::string& error) = 0;
  // ImageBufAlgo::paste of all of `source` at (x, y).
  virtual void paste(int x, int y, const Canvas& source) = 0;
  // The same with 8-bit RGBA pixels the caller owns.
  virtual void pasteRgba8(int x, int y, int width, int height, const uint8_t* pixels) = 0;
  virtual std::unique_ptr<Canvas> rotated270() const = 0;
  virtual void getRgba8(uint8_t* out) const = 0;
};

class Module {
 public:
  virtual ~Module() = default;
  virtual uint32_t interfaceVersion() const = 0;
  virtual std::unique_ptr<ImageFile> openImage(const std::string& path) = 0;
  // Encodes into `bytes` in memory (IOVecOutput); the format from the
  // extension of `path`. `stored` is the file's pixel type, `given` that of
  // `pixels` (width x height x 4). `attributes` are string attributes of the
  // spec, in order.
  virtual bool encode(const std::string& path, int width, int height, PixelType stored,
                      PixelType given, const void* pixels,
                      const std::vector<std::pair<std::string, std::string>>& attributes,
                      std::vector<unsigned char>& bytes, std::string& error) = 0;
  // An animated, looping GIF of RGBA8 frames written to `file` (giflib needs
  // a file). False with the reason if this OpenImageIO cannot, or it failed.
  virtual bool writeGif(const std::string& file, int width, int height,
                        const std::vector<const uint8_t*>& frames, int framesPerSecond,
                        std::string& error) = 0;
  virtual std::unique_ptr<Canvas> createCanvas(int width, int height, PixelType type) = 0;
  virtual TextBox textSize(const std::string& text, int size, const std::string& font) = 0;
};

// The entry point the module exports (extern "C", so dlsym finds it by name).
inline constexpr const char* kEntryPoint = "shadelab_oiio_module";
using EntryPoint = Module* (*)();

// The module, loaded on first use. Throws InputError if it cannot be loaded:
// "cannot <purpose>: it needs shadelab's OpenImageIO module, ..." with the
// places searched and the loader's reason. Searched, in order: the file
// named by $SHADELAB_OIIO_MODULE; libshadelab_oiio.so beside the executable
// (build tree); <executable>/../<libdir>/shadelab/ (installed tree); then
// dlopen's own search (RUNPATH, LD_LIBRARY_PATH: programs built against an
// installed shadelab get a RUNPATH to it).
Module& oiioModule(const std::string& purpose);
// Whether this process has loaded the module (for tests and diagnostics).
bool oiioModuleLoaded();

}  // namespace shadelab::oiio
