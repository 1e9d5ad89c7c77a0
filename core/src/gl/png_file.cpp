#include <gdal_priv.h>

#include <cstring>
#include <memory>

#include <strata/error.hpp>
#include <strata/output.hpp>

namespace strata {

std::vector<unsigned char> readPixels(const Framebuffer& framebuffer) {
  const int width = framebuffer.width(), height = framebuffer.height();
  const auto rowBytes = static_cast<std::size_t>(width) * 4;
  std::vector<unsigned char> bottomUp(rowBytes * static_cast<std::size_t>(height));
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(framebuffer.color(0).id(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                    static_cast<GLsizei>(bottomUp.size()), bottomUp.data());
  std::vector<unsigned char> topDown(bottomUp.size());
  for (int row = 0; row < height; ++row)
    std::memcpy(&topDown[static_cast<std::size_t>(row) * rowBytes],
                &bottomUp[static_cast<std::size_t>(height - 1 - row) * rowBytes], rowBytes);
  return topDown;
}

namespace {

// GDAL's last error without its trailing newline.
std::string lastGdalError() {
  std::string message = CPLGetLastErrorMsg();
  while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
  return message;
}

}  // namespace

void writePng(const std::filesystem::path& file, int width, int height, const std::vector<unsigned char>& rgba) {
  static const bool registered = (GDALAllRegister(), true);  // once, even with several threads writing
  (void)registered;
  GDALDriver* memory = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDriver* png = GetGDALDriverManager()->GetDriverByName("PNG");
  SourceLocation where{file.string()};
  if (!memory || !png) throw Error(where, "this GDAL has no PNG driver", "install a GDAL built with libpng");
  std::unique_ptr<GDALDataset> image(memory->Create("", width, height, 4, GDT_Byte, nullptr));
  CPLErr status = image->RasterIO(GF_Write, 0, 0, width, height, const_cast<unsigned char*>(rgba.data()), width,
                                  height, GDT_Byte, 4, nullptr, 4, 4 * width, 1);
  if (status != CE_None) throw Error(where, "could not stage the image for writing: " + lastGdalError());
  std::error_code ignored;
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path(), ignored);
  CPLErrorReset();
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", "NO");  // no .aux.xml side-car beside the PNG
  CPLPushErrorHandler(CPLQuietErrorHandler);                 // the failure is reported once, below
  std::unique_ptr<GDALDataset> written(png->CreateCopy(file.c_str(), image.get(), FALSE, nullptr, nullptr, nullptr));
  written.reset();  // closing flushes the file
  CPLPopErrorHandler();
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", nullptr);
  if (CPLGetLastErrorType() >= CE_Failure || !std::filesystem::exists(file))
    throw Error(where, "cannot write the image: " + lastGdalError(),
                "choose an output path in a directory you can write to");
}

}  // namespace strata
