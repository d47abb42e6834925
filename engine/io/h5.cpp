#include "h5.h"

#include "core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace beverloo {
namespace {

[[noreturn]] void fail(const std::string& what) { throw IoError("HDF5: " + what); }

/// The name of the file holding `loc` ("" if HDF5 cannot say), for an error message.
std::string file_of(hid_t loc) {
  const ssize_t n = H5Fget_name(loc, nullptr, 0);
  if (n <= 0) return "";
  std::string name(static_cast<std::size_t>(n) + 1, '\0');
  H5Fget_name(loc, name.data(), name.size());
  name.resize(static_cast<std::size_t>(n));
  return name;
}

/// ": <the system's reason>" after a failed HDF5 call that reached the system (HDF5 leaves the
/// errno of its open() or write(): ENOSPC on a full disk), else nothing.
std::string system_reason() { return errno ? std::string(": ") + std::strerror(errno) : std::string(); }

template <typename T>
hid_t native_type();
template <> hid_t native_type<double>() { return H5T_NATIVE_DOUBLE; }
template <> hid_t native_type<std::int64_t>() { return H5T_NATIVE_INT64; }
template <> hid_t native_type<std::uint64_t>() { return H5T_NATIVE_UINT64; }
template <> hid_t native_type<std::uint8_t>() { return H5T_NATIVE_UINT8; }
template <> hid_t native_type<std::int32_t>() { return H5T_NATIVE_INT32; }

template <typename T>
void write_impl(hid_t loc, const std::string& name, const std::vector<T>& data, std::vector<hsize_t> dims) {
  if (dims.empty()) dims = {static_cast<hsize_t>(data.size())};
  H5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), H5Sclose);
  if (space.id() < 0) fail("dataspace for " + name);
  // Fletcher-32 over the data (HDF5 filters need a chunked layout): a damaged byte makes the
  // read fail instead of handing a state that was never simulated to a resumed run. One chunk
  // per dataset up to 64 MiB, else slabs of rows.
  H5Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  if (!data.empty()) {
    std::vector<hsize_t> chunk = dims;
    hsize_t row_bytes = sizeof(T);
    for (std::size_t k = 1; k < dims.size(); ++k) row_bytes *= dims[k];
    chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], (hsize_t{64} << 20) / row_bytes));
    if (H5Pset_chunk(dcpl, static_cast<int>(chunk.size()), chunk.data()) < 0 || H5Pset_fletcher32(dcpl) < 0)
      fail("checksummed layout for " + name);
  }
  H5Handle dset(H5Dcreate2(loc, name.c_str(), native_type<T>(), space, H5P_DEFAULT, dcpl, H5P_DEFAULT), H5Dclose);
  if (dset.id() < 0) fail("create dataset " + name);
  errno = 0;
  if (!data.empty() && H5Dwrite(dset, native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) < 0)
    fail("cannot write dataset " + name + " of " + file_of(loc) + system_reason());
  // the data written above may only reach the file here (the sieve buffer): a close that failed
  // leaves a hole where the data belong, read back as zeros once the file grows past it
  if (!dset.close()) fail("cannot write dataset " + name + " of " + file_of(loc) + system_reason());
}

template <typename T>
std::vector<T> read_impl(hid_t loc, const std::string& name) {
  H5Handle dset(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (dset.id() < 0) fail("open dataset " + name);
  H5Handle space(H5Dget_space(dset), H5Sclose);
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  std::vector<T> out(static_cast<std::size_t>(n));
  if (n > 0 && H5Dread(dset, native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()) < 0)
    fail("read dataset " + name);
  return out;
}

template <typename T>
void scalar_attr(hid_t loc, const std::string& name, T value) {
  if (H5Aexists(loc, name.c_str()) > 0) H5Adelete(loc, name.c_str());
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Handle a(H5Acreate2(loc, name.c_str(), native_type<T>(), space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (a.id() < 0 || H5Awrite(a, native_type<T>(), &value) < 0) fail("write attribute " + name);
}

template <typename T>
T read_scalar_attr(hid_t loc, const std::string& name) {
  H5Handle a(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose);
  T value{};
  if (a.id() < 0 || H5Aread(a, native_type<T>(), &value) < 0) fail("read attribute " + name);
  return value;
}

}  // namespace

namespace h5 {

void init_library() {
  H5dont_atexit();  // must come before every other HDF5 call
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

H5Handle create_file(const std::string& path, FileFormat format) {
  // The 1.10 file format at least: its superblock, object headers (attributes included) and
  // chunk indexes carry checksums, which the 1.8 format's B-trees do not; with the datasets'
  // Fletcher-32 (write_impl) damage anywhere in a file is seen when it is read.
  H5Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (format == FileFormat::Checksummed && H5Pset_libver_bounds(fapl, H5F_LIBVER_V110, H5F_LIBVER_LATEST) < 0)
    fail("file format bounds for " + path);
  errno = 0;
  H5Handle f(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), H5Fclose);
  if (f.id() < 0) fail("cannot create " + path + system_reason());
  return f;
}
void flush(hid_t file, const std::string& path) {
  errno = 0;
  if (H5Fflush(file, H5F_SCOPE_GLOBAL) < 0) fail("cannot write " + path + system_reason());
}
H5Handle open_file(const std::string& path, bool writable) {
  H5Handle f(H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (f.id() < 0) fail("cannot open " + path);
  return f;
}
H5Handle create_group(hid_t loc, const std::string& name) {
  H5Handle g(H5Gcreate2(loc, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (g.id() < 0) fail("create group " + name);
  return g;
}
H5Handle open_group(hid_t loc, const std::string& name) {
  H5Handle g(H5Gopen2(loc, name.c_str(), H5P_DEFAULT), H5Gclose);
  if (g.id() < 0) fail("open group " + name);
  return g;
}
bool exists(hid_t loc, const std::string& name) { return H5Lexists(loc, name.c_str(), H5P_DEFAULT) > 0; }

void write(hid_t l, const std::string& n, const std::vector<double>& d, std::vector<hsize_t> s) { write_impl(l, n, d, s); }
void write(hid_t l, const std::string& n, const std::vector<std::int64_t>& d, std::vector<hsize_t> s) { write_impl(l, n, d, s); }
void write(hid_t l, const std::string& n, const std::vector<std::uint64_t>& d, std::vector<hsize_t> s) { write_impl(l, n, d, s); }
void write(hid_t l, const std::string& n, const std::vector<std::uint8_t>& d, std::vector<hsize_t> s) { write_impl(l, n, d, s); }
void write(hid_t l, const std::string& n, const std::vector<std::int32_t>& d, std::vector<hsize_t> s) { write_impl(l, n, d, s); }
std::vector<double> read_doubles(hid_t l, const std::string& n) { return read_impl<double>(l, n); }
std::vector<std::int64_t> read_int64(hid_t l, const std::string& n) { return read_impl<std::int64_t>(l, n); }
std::vector<std::uint64_t> read_uint64(hid_t l, const std::string& n) { return read_impl<std::uint64_t>(l, n); }
std::vector<std::uint8_t> read_uint8(hid_t l, const std::string& n) { return read_impl<std::uint8_t>(l, n); }

void attr(hid_t loc, const std::string& name, double value) { scalar_attr(loc, name, value); }
void attr(hid_t loc, const std::string& name, std::int64_t value) { scalar_attr(loc, name, value); }
void attr(hid_t loc, const std::string& name, const std::vector<std::int32_t>& values) {
  if (H5Aexists(loc, name.c_str()) > 0) H5Adelete(loc, name.c_str());
  const hsize_t n = values.size();
  H5Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  H5Handle a(H5Acreate2(loc, name.c_str(), H5T_NATIVE_INT32, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (a.id() < 0 || H5Awrite(a, H5T_NATIVE_INT32, values.data()) < 0) fail("write attribute " + name);
}
void attr(hid_t loc, const std::string& name, const std::string& value) {
  if (H5Aexists(loc, name.c_str()) > 0) H5Adelete(loc, name.c_str());
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, value.empty() ? 1 : value.size());
  H5Tset_cset(type, H5T_CSET_UTF8);
  H5Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  H5Handle a(H5Acreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (a.id() < 0 || H5Awrite(a, type, value.empty() ? "" : value.data()) < 0) fail("write attribute " + name);
}
void attr(hid_t loc, const std::string& name, const std::vector<std::string>& values) {
  // fixed-length string array (H5MD's box/boundary is one)
  std::size_t len = 1;
  for (const auto& v : values) len = std::max(len, v.size());
  std::vector<char> buf(len * values.size(), '\0');
  for (std::size_t k = 0; k < values.size(); ++k) std::memcpy(&buf[k * len], values[k].data(), values[k].size());
  if (H5Aexists(loc, name.c_str()) > 0) H5Adelete(loc, name.c_str());
  H5Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type, len);
  const hsize_t n = values.size();
  H5Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose);
  H5Handle a(H5Acreate2(loc, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (a.id() < 0 || H5Awrite(a, type, buf.data()) < 0) fail("write attribute " + name);
}
double attr_double(hid_t loc, const std::string& name) { return read_scalar_attr<double>(loc, name); }
std::int64_t attr_int64(hid_t loc, const std::string& name) { return read_scalar_attr<std::int64_t>(loc, name); }
std::string attr_string(hid_t loc, const std::string& name) {
  H5Handle a(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (a.id() < 0) fail("read attribute " + name);
  H5Handle type(H5Aget_type(a), H5Tclose);
  const std::size_t size = H5Tget_size(type);
  std::string out(size, '\0');
  H5Handle mem(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(mem, size);
  H5Tset_cset(mem, H5Tget_cset(type));  // HDF5 does not convert between ASCII and UTF-8
  if (H5Aread(a, mem, out.data()) < 0) fail("read attribute " + name);
  while (!out.empty() && out.back() == '\0') out.pop_back();
  return out;
}

}  // namespace h5

}  // namespace beverloo
