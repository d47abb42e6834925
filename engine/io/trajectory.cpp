#include "trajectory.h"
#include "core/version.h"

#include <filesystem>

namespace beverloo {
namespace {

H5Handle extendible(hid_t loc, const std::string& name, hid_t type, std::vector<hsize_t> frame_dims) {
  std::vector<hsize_t> dims{0}, max{H5S_UNLIMITED}, chunk{1};
  for (hsize_t d : frame_dims) {
    dims.push_back(d);
    max.push_back(d);
    chunk.push_back(d);
  }
  if (frame_dims.empty()) chunk[0] = 256;
  H5Handle space(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), max.data()), H5Sclose);
  H5Handle plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  H5Pset_chunk(plist, static_cast<int>(chunk.size()), chunk.data());
  H5Pset_fletcher32(plist);  // a damaged frame fails to read (h5.cpp, write_impl)
  H5Handle d(H5Dcreate2(loc, name.c_str(), type, space, H5P_DEFAULT, plist, H5P_DEFAULT), H5Dclose);
  if (d.id() < 0) throw IoError("HDF5: create " + name);
  return d;
}

void append(hid_t loc, const std::string& name, hid_t type, const void* data, std::int64_t frame) {
  H5Handle d(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  H5Handle space(H5Dget_space(d), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(rank);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  dims[0] = frame + 1;
  if (H5Dset_extent(d, dims.data()) < 0) throw IoError("HDF5: extend " + name);
  H5Handle fspace(H5Dget_space(d), H5Sclose);
  std::vector<hsize_t> start(rank, 0), count = dims;
  start[0] = frame;
  count[0] = 1;
  H5Sselect_hyperslab(fspace, H5S_SELECT_SET, start.data(), nullptr, count.data(), nullptr);
  H5Handle mspace(H5Screate_simple(rank, count.data(), nullptr), H5Sclose);
  if (H5Dwrite(d, type, mspace, fspace, H5P_DEFAULT, data) < 0) throw IoError("HDF5: write " + name);
}

void truncate(hid_t loc, const std::string& name, hsize_t frames) {
  H5Handle d(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose);
  H5Handle space(H5Dget_space(d), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space);
  std::vector<hsize_t> dims(rank);
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  dims[0] = frames;
  if (H5Dset_extent(d, dims.data()) < 0) throw IoError("HDF5: truncate " + name);
}

}  // namespace

template <int D>
H5mdTrajectory<D>::H5mdTrajectory(const std::string& path, const SimConfig& c, const ParticleState<D>& s,
                                  double box_height, std::int64_t keep_until_step) {
  buffer_.resize(static_cast<std::size_t>(s.size()) * D);
  if (keep_until_step >= 0 && std::filesystem::exists(path)) {
    try {
      file_ = h5::open_file(path, true);
      const std::vector<std::int64_t> steps = h5::read_int64(file_, "particles/all/position/step");
      std::int64_t keep = 0;
      while (keep < static_cast<std::int64_t>(steps.size()) && steps[keep] <= keep_until_step) ++keep;
      for (const char* n : {"particles/all/position/step", "particles/all/position/time", "particles/all/position/value"})
        truncate(file_, n, keep);
      frames_ = keep;
      return;
    } catch (const IoError&) {
      // a kill during a frame write can leave the file unreadable: keep it aside, start anew
      file_.reset();
      std::filesystem::rename(path, path + ".corrupt");
    }
  }
  create(path, c, s, box_height);
}

template <int D>
void H5mdTrajectory<D>::create(const std::string& path, const SimConfig& c, const ParticleState<D>& s,
                               double box_height) {
  file_ = h5::create_file(path, h5::FileFormat::Appendable);  // reopened to append after a kill (h5.h)
  {
    H5Handle h5md = h5::create_group(file_, "h5md");
    h5::attr(h5md, "version", std::vector<std::int32_t>{1, 1});
    H5Handle author = h5::create_group(h5md, "author");
    h5::attr(author, "name", std::string("beverloo"));
    H5Handle creator = h5::create_group(h5md, "creator");
    h5::attr(creator, "name", std::string("beverloo"));
    h5::attr(creator, "version", std::string(BEVERLOO_VERSION));
  }
  H5Handle particles = h5::create_group(file_, "particles");
  H5Handle all = h5::create_group(particles, "all");
  {
    H5Handle box = h5::create_group(all, "box");
    h5::attr(box, "dimension", std::vector<std::int32_t>{D});
    h5::attr(box, "boundary", std::vector<std::string>(D, "none"));
    std::vector<double> edges(D, c.W);
    edges[D - 1] = box_height;
    h5::write(box, "edges", edges);
  }
  std::vector<std::int32_t> species(s.size());
  std::vector<double> diameter(s.size());
  for (int i = 0; i < s.size(); ++i) {  // in id order, as the frames
    species[s.id[i]] = s.species[i];
    diameter[s.id[i]] = s.sigma(i);
  }
  h5::write(all, "species", species);
  h5::write(all, "diameter", diameter);
  H5Handle pos = h5::create_group(all, "position");
  extendible(pos, "step", H5T_NATIVE_INT64, {});
  extendible(pos, "time", H5T_NATIVE_DOUBLE, {});
  extendible(pos, "value", H5T_NATIVE_DOUBLE, {static_cast<hsize_t>(s.size()), static_cast<hsize_t>(D)});
  H5Handle params = h5::create_group(file_, "parameters");
  h5::attr(params, "W", c.W);
  h5::attr(params, "w", c.w);
  h5::attr(params, "theta_w_left_deg", c.theta_w_left_deg);
  h5::attr(params, "theta_w_right_deg", c.theta_w_right_deg);
  h5::attr(params, "job", c.to_json().dump());
  h5::flush(file_, "trajectory.h5");  // a header that did not reach the disk is an I/O error
}

template <int D>
void H5mdTrajectory<D>::write_frame(const ParticleState<D>& s, double time) {
  // rows in id order: a model may keep its particles in another (SP sorts them by cell)
  for (int i = 0; i < s.size(); ++i)
    for (int d = 0; d < D; ++d) buffer_[static_cast<std::size_t>(s.id[i]) * D + d] = s.x[i][d];
  append(file_, "particles/all/position/value", H5T_NATIVE_DOUBLE, buffer_.data(), frames_);
  const std::int64_t step = s.step;
  append(file_, "particles/all/position/step", H5T_NATIVE_INT64, &step, frames_);
  append(file_, "particles/all/position/time", H5T_NATIVE_DOUBLE, &time, frames_);
  ++frames_;
  h5::flush(file_, "trajectory.h5");  // a frame that did not reach the disk is an I/O error
}

template class H5mdTrajectory<2>;
template class H5mdTrajectory<3>;

}  // namespace beverloo
