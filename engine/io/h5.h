#pragma once
/// \file h5.h
/// \brief A thin RAII layer over the HDF5 C API: files, groups, 1D/2D datasets and scalar
/// attributes of the types we store. Every failure throws IoError naming the object.
#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"

namespace beverloo {

class H5Handle {
 public:
  H5Handle() = default;
  H5Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  H5Handle(H5Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  H5Handle& operator=(H5Handle&& o) noexcept {
    reset();
    id_ = o.id_;
    close_ = o.close_;
    o.id_ = -1;
    return *this;
  }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  ~H5Handle() { reset(); }
  hid_t id() const { return id_; }
  operator hid_t() const { return id_; }
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = -1;
  }
  /// Closes now and says whether HDF5 could (reset() ignores it, as a destructor must). A
  /// dataset's raw data may still sit in HDF5's sieve buffer after H5Dwrite and reaches the file
  /// only at H5Dclose: on a full disk that close is where the write fails.
  bool close() {
    const herr_t rc = id_ >= 0 && close_ ? close_(id_) : 0;
    id_ = -1;
    return rc >= 0;
  }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

namespace h5 {
/// Checksummed: the HDF5 1.10 format, whose headers and indexes carry checksums (h5.cpp), for a
/// file written whole and then renamed into place. Appendable: the library's earliest format,
/// for a file kept open for writing across a run that may be killed (the trajectory): the 1.10
/// format marks a file open for writing in its superblock, and after a kill HDF5 refuses to
/// reopen it until `h5clear -s`, which would lose a resumed run's earlier frames.
enum class FileFormat { Checksummed, Appendable };
H5Handle create_file(const std::string& path, FileFormat format = FileFormat::Checksummed);  ///< truncates
/// Writes everything of `file` to the disk; throws IoError naming `path` if that fails (a full
/// disk): a file whose flush failed is incomplete and must not be committed under its name.
void flush(hid_t file, const std::string& path);
H5Handle open_file(const std::string& path, bool writable = false);
H5Handle create_group(hid_t loc, const std::string& name);
H5Handle open_group(hid_t loc, const std::string& name);
bool exists(hid_t loc, const std::string& name);

void write(hid_t loc, const std::string& name, const std::vector<double>& data, std::vector<hsize_t> dims = {});
void write(hid_t loc, const std::string& name, const std::vector<std::int64_t>& data, std::vector<hsize_t> dims = {});
void write(hid_t loc, const std::string& name, const std::vector<std::uint64_t>& data, std::vector<hsize_t> dims = {});
void write(hid_t loc, const std::string& name, const std::vector<std::uint8_t>& data, std::vector<hsize_t> dims = {});
void write(hid_t loc, const std::string& name, const std::vector<std::int32_t>& data, std::vector<hsize_t> dims = {});
std::vector<double> read_doubles(hid_t loc, const std::string& name);
std::vector<std::int64_t> read_int64(hid_t loc, const std::string& name);
std::vector<std::uint64_t> read_uint64(hid_t loc, const std::string& name);
std::vector<std::uint8_t> read_uint8(hid_t loc, const std::string& name);

void attr(hid_t loc, const std::string& name, double value);
void attr(hid_t loc, const std::string& name, std::int64_t value);
void attr(hid_t loc, const std::string& name, const std::string& value);
void attr(hid_t loc, const std::string& name, const std::vector<std::int32_t>& values);
void attr(hid_t loc, const std::string& name, const std::vector<std::string>& values);
double attr_double(hid_t loc, const std::string& name);
std::int64_t attr_int64(hid_t loc, const std::string& name);
std::string attr_string(hid_t loc, const std::string& name);

/// Call once, before any other HDF5 use: HDF5 installs no clean-up at exit, and is quiet (we
/// report errors ourselves). Why no clean-up: a write that failed for want of room can leave a
/// file HDF5 could not close, and its clean-up at exit closes it again and crashes
/// (H5F__close_cb in H5_term_library, HDF5 1.10; a `simulate` on a full tmpfs ended with
/// SIGSEGV instead of its exit code, and so did campaign workers). Our files are closed by their
/// handles and written under temporary names, so the clean-up had nothing of ours to do.
void init_library();
}  // namespace h5

}  // namespace beverloo
