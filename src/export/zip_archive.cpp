#include "export/zip_archive.hpp"

#include <fmt/format.h>
#include <zip.h>

#include <memory>
#include <stdexcept>

namespace wobble::exports {

namespace {
struct ZipSourceDeleter {
  void operator()(zip_source_t* s) const { zip_source_free(s); }
};

[[noreturn]] void zip_failed(const std::string& what, zip_error_t* error) {
  const std::string message = fmt::format("zip: {}: {}", what, zip_error_strerror(error));
  zip_error_fini(error);
  throw std::runtime_error(message);
}
}  // namespace

std::string zip_archive(const std::vector<OutputFile>& files) {
  zip_error_t error;
  zip_error_init(&error);
  std::unique_ptr<zip_source_t, ZipSourceDeleter> buffer(
      zip_source_buffer_create(nullptr, 0, 0, &error));
  if (!buffer) zip_failed("cannot make a buffer", &error);
  zip_source_keep(buffer.get());  // the archive's close frees it once; we read it after
  zip_t* archive = zip_open_from_source(buffer.get(), ZIP_TRUNCATE, &error);
  if (archive == nullptr) zip_failed("cannot open the archive", &error);
  for (const auto& f : files) {
    zip_source_t* data = zip_source_buffer(archive, f.content.data(), f.content.size(), 0);
    const zip_int64_t index =
        data ? zip_file_add(archive, f.path.c_str(), data, ZIP_FL_ENC_UTF_8) : -1;
    if (index < 0) {
      if (data) zip_source_free(data);
      const std::string message = zip_strerror(archive);
      zip_discard(archive);
      throw std::runtime_error("zip: cannot add " + f.path + ": " + message);
    }
    const auto i = static_cast<zip_uint64_t>(index);
    // A .deb is compressed already: stored, not deflated again.
    if (f.path.size() > 4 && f.path.compare(f.path.size() - 4, 4, ".deb") == 0) {
      zip_set_file_compression(archive, i, ZIP_CM_STORE, 0);
    }
    const zip_uint32_t mode = f.executable ? 0100755 : 0100644;
    zip_file_set_external_attributes(archive, i, 0, ZIP_OPSYS_UNIX, mode << 16);
  }
  if (zip_close(archive) < 0) {
    const std::string message = zip_strerror(archive);
    zip_discard(archive);
    throw std::runtime_error("zip: cannot write the archive: " + message);
  }
  zip_source_t* src = buffer.get();
  zip_stat_t stat;
  if (zip_source_stat(src, &stat) < 0 || zip_source_open(src) < 0) {
    throw std::runtime_error("zip: cannot read the archive back");
  }
  std::string out(static_cast<std::size_t>(stat.size), '\0');
  const zip_int64_t got = zip_source_read(src, out.data(), stat.size);
  zip_source_close(src);
  if (got < 0 || static_cast<zip_uint64_t>(got) != stat.size) {
    throw std::runtime_error("zip: cannot read the archive back");
  }
  zip_error_fini(&error);
  return out;
}

}  // namespace wobble::exports
