// libshadelab_oiio.so: the one place that links OpenImageIO, loaded with
// dlopen on first use (core/base/oiio_module.h says why). Each function is
// the OpenImageIO call its caller made before the module existed.
#include "core/base/oiio_module.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

namespace shadelab::oiio {
namespace {

namespace IBA = OIIO::ImageBufAlgo;

OIIO::TypeDesc typeDesc(PixelType type) {
  switch (type) {
    case PixelType::UInt8:
      return OIIO::TypeDesc::UINT8;
    case PixelType::UInt16:
      return OIIO::TypeDesc::UINT16;
    case PixelType::Half:
      return OIIO::TypeDesc::HALF;
    case PixelType::Float:
      return OIIO::TypeDesc::FLOAT;
    case PixelType::Double:
      return OIIO::TypeDesc::DOUBLE;
    case PixelType::Other:
      break;
  }
  return OIIO::TypeDesc::UNKNOWN;
}

PixelType pixelType(OIIO::TypeDesc type) {
  switch (type.basetype) {
    case OIIO::TypeDesc::UINT8:
      return PixelType::UInt8;
    case OIIO::TypeDesc::UINT16:
      return PixelType::UInt16;
    case OIIO::TypeDesc::HALF:
      return PixelType::Half;
    case OIIO::TypeDesc::FLOAT:
      return PixelType::Float;
    case OIIO::TypeDesc::DOUBLE:
      return PixelType::Double;
    default:
      return PixelType::Other;
  }
}

class OiioImageFile final : public ImageFile {
 public:
  explicit OiioImageFile(const std::string& path) : path_(path), buffer_(path) {}
  bool readHeader(ImageHeader& header, std::string& error) override {
    if (!buffer_.init_spec(path_, 0, 0)) return error = buffer_.geterror(), false;
    header = this->header();
    return true;
  }
  bool read(int subimage, PixelType as, std::string& error) override {
    if (!buffer_.read(subimage, 0, true, typeDesc(as))) return error = buffer_.geterror(), false;
    return true;
  }
  ImageHeader header() const override {
    const OIIO::ImageSpec& spec = buffer_.spec();
    return {spec.width, spec.height, spec.nchannels, pixelType(buffer_.nativespec().format)};
  }
  void getRows(int yBegin, int yEnd, PixelType as, void* out) const override {
    const OIIO::ImageSpec& spec = buffer_.spec();
    buffer_.get_pixels(OIIO::ROI(0, spec.width, yBegin, yEnd, 0, 1, 0, spec.nchannels),
                       typeDesc(as), out);
  }

 private:
  std::string path_;
  OIIO::ImageBuf buffer_;
};

class OiioCanvas final : public Canvas {
 public:
  explicit OiioCanvas(OIIO::ImageBuf buffer) : buffer_(std::move(buffer)) {}
  int width() const override { return buffer_.spec().width; }
  int height() const override { return buffer_.spec().height; }
  void fill(const float color[4]) override { IBA::fill(buffer_, {color, 4}); }
  void setPixel(int x, int y, const float color[4]) override { buffer_.setpixel(x, y, color, 4); }
  void line(int x0, int y0, int x1, int y1, const float color[4],
            std::optional<Clip> clip) override {
    if (clip)
      IBA::render_line(buffer_, x0, y0, x1, y1, {color, 4}, false,
                       OIIO::ROI(clip->xBegin, clip->xEnd, clip->yBegin, clip->yEnd, 0, 1, 0, 4));
    else
      IBA::render_line(buffer_, x0, y0, x1, y1, {color, 4});
  }
  void box(int x0, int y0, int x1, int y1, const float color[4]) override {
    IBA::render_box(buffer_, x0, y0, x1, y1, {color, 4});
  }
  bool text(int x, int y, const std::string& text, int size, const std::string& font,
            const float color[4], AlignX alignX, AlignY alignY, std::string& error) override {
    if (IBA::render_text(buffer_, x, y, text, size, font, {color, 4}, IBA::TextAlignX(int(alignX)),
                         IBA::TextAlignY(int(alignY))))
      return true;
    error = buffer_.geterror();
    return false;
  }
  void paste(int x, int y, const Canvas& source) override {
    IBA::paste(buffer_, x, y, 0, 0, static_cast<const OiioCanvas&>(source).buffer_);
  }
  void pasteRgba8(int x, int y, int width, int height, const uint8_t* pixels) override {
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    OIIO::ImageBuf image(spec, const_cast<uint8_t*>(pixels));
    IBA::paste(buffer_, x, y, 0, 0, image);
  }
  std::unique_ptr<Canvas> rotated270() const override {
    return std::make_unique<OiioCanvas>(IBA::rotate270(buffer_));
  }
  void getRgba8(uint8_t* out) const override {
    const OIIO::ImageSpec& spec = buffer_.spec();
    buffer_.get_pixels(OIIO::ROI(0, spec.width, 0, spec.height, 0, 1, 0, 4), OIIO::TypeDesc::UINT8,
                       out);
  }

 private:
  OIIO::ImageBuf buffer_;
};

class OiioModule final : public Module {
 public:
  uint32_t interfaceVersion() const override { return kInterfaceVersion; }

  std::unique_ptr<ImageFile> openImage(const std::string& path) override {
    return std::make_unique<OiioImageFile>(path);
  }

  bool encode(const std::string& path, int width, int height, PixelType stored, PixelType given,
              const void* pixels,
              const std::vector<std::pair<std::string, std::string>>& attributes,
              std::vector<unsigned char>& bytes, std::string& error) override {
    OIIO::ImageSpec spec(width, height, 4, typeDesc(stored));
    for (const auto& [name, value] : attributes) spec.attribute(name, value);
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create(path);
    if (!output) return error = OIIO::geterror(), false;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    bool encoded = output->set_ioproxy(&memory) && output->open(path, spec) &&
                   output->write_image(typeDesc(given), pixels);
    encoded = output->close() && encoded;
    if (!encoded || output->has_error()) return error = output->geterror(), false;
    return true;
  }

  bool writeGif(const std::string& file, int width, int height,
                const std::vector<const uint8_t*>& frames, int framesPerSecond,
                std::string& error) override {
    std::unique_ptr<OIIO::ImageOutput> output = OIIO::ImageOutput::create("gif");
    if (!output || !output->supports("multiimage"))
      return error = "this OpenImageIO has no animated GIF writer", false;
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
    int rate[2] = {framesPerSecond, 1};
    spec.attribute("FramesPerSecond", OIIO::TypeRational, rate);
    spec.attribute("gif:LoopCount", 0);  // for ever
    std::vector<OIIO::ImageSpec> specs(frames.size(), spec);
    bool encoded = output->open(file, int(specs.size()), specs.data());
    for (size_t i = 0; encoded && i < frames.size(); ++i)
      encoded = (i == 0 || output->open(file, spec, OIIO::ImageOutput::AppendSubimage)) &&
                output->write_image(OIIO::TypeDesc::UINT8, frames[i]);
    encoded = output->close() && encoded;
    if (!encoded || output->has_error()) return error = output->geterror(), false;
    return true;
  }

  std::unique_ptr<Canvas> createCanvas(int width, int height, PixelType type) override {
    return std::make_unique<OiioCanvas>(
        OIIO::ImageBuf(OIIO::ImageSpec(width, height, 4, typeDesc(type))));
  }

  TextBox textSize(const std::string& text, int size, const std::string& font) override {
    OIIO::ROI box = IBA::text_size(text, size, font);
    return {box.xbegin, box.xend, box.ybegin, box.yend};
  }
};

}  // namespace
}  // namespace shadelab::oiio

extern "C" __attribute__((visibility("default"))) shadelab::oiio::Module* shadelab_oiio_module() {
  static shadelab::oiio::OiioModule module;
  return &module;
}
