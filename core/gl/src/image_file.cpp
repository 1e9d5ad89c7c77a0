#include <gdal_priv.h>

#include <cctype>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>

#include <strata/error.hpp>
#include <strata/plugin/output.hpp>

namespace strata {
namespace {

// GDAL's last error without its trailing newline.
std::string lastGdalError() {
  std::string message = CPLGetLastErrorMsg();
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  return message;
}

// Rows of `bottomUp` (as GL reads them) in the order images are written, top row first.
template <typename T>
std::vector<T> topRowFirst(const std::vector<T>& bottomUp, int height) {
  const auto row = static_cast<std::size_t>(bottomUp.size() / static_cast<std::size_t>(height));
  std::vector<T> topDown(bottomUp.size());
  for (int y = 0; y < height; ++y)
    std::memcpy(&topDown[static_cast<std::size_t>(y) * row], &bottomUp[static_cast<std::size_t>(height - 1 - y) * row],
                row * sizeof(T));
  return topDown;
}

}  // namespace

std::vector<unsigned char> readPixels(const Framebuffer& framebuffer) {
  const int width = framebuffer.width(), height = framebuffer.height();
  std::vector<unsigned char> bottomUp(static_cast<std::size_t>(width) * 4 * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(framebuffer.color(0).id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(bottomUp.size()),
                    bottomUp.data());
  return topRowFirst(bottomUp, height);
}

std::vector<float> readDepth(const Framebuffer& framebuffer) {
  if (framebuffer.samples() > 1)
    throw std::invalid_argument("readDepth: the framebuffer holds " + std::to_string(framebuffer.samples()) +
                                " depths per pixel; draw it with antialiasing: none to read depths at pixel centres");
  const int width = framebuffer.width(), height = framebuffer.height();
  std::vector<float> bottomUp(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glGetTextureImage(framebuffer.depth().id(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(bottomUp.size() * sizeof(float)), bottomUp.data());
  return topRowFirst(bottomUp, height);
}

ImageFormat imageFormatOf(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".png") return ImageFormat::Png;
  if (extension == ".tif" || extension == ".tiff") return ImageFormat::Tiff;
  throw Error(SourceLocation{file.string()},
              "cannot write an image named '" + extension + "'" +
                  (extension == ".exr" ? ": EXR is not written yet (the frame is 8-bit and display-encoded)" : ""),
              "name the file .png or .tif");
}

void writeImage(const std::filesystem::path& file, int width, int height, const std::vector<unsigned char>& rgba) {
  static const bool registered = (GDALAllRegister(), true);  // once, even with several threads writing
  (void)registered;
  SourceLocation where{file.string()};
  const char* driverName = imageFormatOf(file) == ImageFormat::Png ? "PNG" : "GTiff";
  GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driverName);
  if (!memory || !driver)
    throw Error(where, std::string("this GDAL has no ") + driverName + " driver", "install Debian's libgdal");
  std::unique_ptr<GDALDataset> image(memory->Create("", width, height, 4, GDT_Byte, nullptr));
  CPLErr status = image->RasterIO(GF_Write, 0, 0, width, height, const_cast<unsigned char*>(rgba.data()), width, height,
                                  GDT_Byte, 4, nullptr, 4, 4 * width, 1);
  if (status != CE_None) throw Error(where, "could not stage the image for writing: " + lastGdalError());
  std::error_code ignored;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ignored);
  CPLErrorReset();
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", "NO");  // no .aux.xml side-car beside the image
  CPLPushErrorHandler(CPLQuietErrorHandler);                // the failure is reported once, below
  std::unique_ptr<GDALDataset> written(driver->CreateCopy(file.c_str(), image.get(), FALSE, nullptr, nullptr, nullptr));
  written.reset();  // closing flushes the file
  CPLPopErrorHandler();
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", nullptr);
  if (CPLGetLastErrorType() >= CE_Failure || !std::filesystem::exists(file))
    throw Error(where, "cannot write the image: " + lastGdalError(),
                "choose an output path in a directory you can write to");
}

}  // namespace strata
