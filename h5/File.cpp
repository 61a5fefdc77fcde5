#include "h5/File.hpp"

#include <filesystem>

#include "h5/ErrorStack.hpp"
#include "h5/H5Error.hpp"

namespace granwave::h5 {
namespace {

// Strong close degree: closing the file closes every object still open in it, so a closed
// file is really closed (flushed, descriptor released) before AtomicFile renames it.
Handle strongCloseAccess(const std::string& name) {
  Handle fapl = propertyListHandle(check(H5Pcreate(H5P_FILE_ACCESS), name, "cannot create"));
  check(H5Pset_fclose_degree(fapl.get(), H5F_CLOSE_STRONG), name, "cannot set close degree");
  return fapl;
}

htri_t isHdf5(const std::string& path) {
#if H5_VERSION_GE(1, 12, 0)
  return H5Fis_accessible(path.c_str(), H5P_DEFAULT);
#else
  return H5Fis_hdf5(path.c_str());
#endif
}

}  // namespace

Handle intermediateGroupCreation() {
  Handle lcpl = propertyListHandle(H5Pcreate(H5P_LINK_CREATE));
  if (!lcpl.valid() || H5Pset_create_intermediate_group(lcpl.get(), 1) < 0) {
    throw H5Error("HDF5: cannot create a link creation property list");
  }
  return lcpl;
}

File File::create(const std::string& path, const std::string& display_name) {
  silenceHdf5Errors();
  const std::string name = display_name.empty() ? path : display_name;
  Handle fapl = strongCloseAccess(name);
  // No object timestamps anywhere (here: the root group), so that the same run gives the
  // same bytes (reproducibility contract).
  Handle fcpl = propertyListHandle(check(H5Pcreate(H5P_FILE_CREATE), name, "cannot create"));
  H5Pset_obj_track_times(fcpl.get(), false);
  hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), fapl.get());
  return File(fileHandle(check(id, name, "cannot create file")), name);
}

File File::openReadOnly(const std::string& path) {
  silenceHdf5Errors();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw H5Error(path + ": no such file");
  if (std::filesystem::is_directory(path, ec)) throw H5Error(path + ": is a directory");
  const htri_t hdf5 = isHdf5(path);
  if (hdf5 < 0) h5::fail(path, "cannot read file");
  if (hdf5 == 0) throw H5Error(path + ": not an HDF5 file");
  Handle fapl = strongCloseAccess(path);
  hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl.get());
  return File(fileHandle(check(id, path, "cannot open HDF5 file")), path);
}

void File::fail(const std::string& what) const { h5::fail(name_, what); }

File File::openReadWrite(const std::string& path, const std::string& display_name) {
  silenceHdf5Errors();
  const std::string name = display_name.empty() ? path : display_name;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw H5Error(name + ": no such file");
  const htri_t hdf5 = isHdf5(path);
  if (hdf5 < 0) h5::fail(name, "cannot read file");
  if (hdf5 == 0) throw H5Error(name + ": not an HDF5 file");
  Handle fapl = strongCloseAccess(name);
  hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDWR, fapl.get());
  return File(fileHandle(check(id, name, "cannot open HDF5 file for writing")), name);
}

void File::flush() {
  if (H5Fflush(file_.get(), H5F_SCOPE_GLOBAL) < 0) fail("cannot flush file");
}

void File::close() {
  if (file_.valid() && file_.close() < 0) fail("cannot close file");
}

void File::createGroup(const std::string& path) {
  if (isGroup(path)) return;
  Handle lcpl = intermediateGroupCreation();
  Handle gcpl = propertyListHandle(H5Pcreate(H5P_GROUP_CREATE));
  H5Pset_obj_track_times(gcpl.get(), false);  // same bytes for the same run
  hid_t id = H5Gcreate2(file_.get(), path.c_str(), lcpl.get(), gcpl.get(), H5P_DEFAULT);
  if (id < 0) fail("cannot create group " + path);
  H5Gclose(id);
}

bool File::exists(const std::string& path) const {
  if (path == "/") return true;
  if (path.empty() || path.front() != '/') return false;
  // H5Lexists fails (rather than answering false) when a parent is missing, so walk down
  // the path one component at a time.
  for (std::size_t slash = path.find('/', 1);; slash = path.find('/', slash + 1)) {
    const std::string prefix = path.substr(0, slash);
    if (H5Lexists(file_.get(), prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) break;
  }
  return H5Oexists_by_name(file_.get(), path.c_str(), H5P_DEFAULT) > 0;  // no dangling link
}

bool File::isGroup(const std::string& path) const {
  if (!exists(path)) return false;
  Handle object = objectHandle(H5Oopen(file_.get(), path.c_str(), H5P_DEFAULT));
  return object.valid() && H5Iget_type(object.get()) == H5I_GROUP;
}

bool File::isDataset(const std::string& path) const {
  if (!exists(path)) return false;
  Handle object = objectHandle(H5Oopen(file_.get(), path.c_str(), H5P_DEFAULT));
  return object.valid() && H5Iget_type(object.get()) == H5I_DATASET;
}

Handle File::openObject(const std::string& path) const {
  if (!exists(path)) throw H5Error(name_ + ": no object " + path);
  hid_t id = H5Oopen(file_.get(), path.c_str(), H5P_DEFAULT);
  if (id < 0) fail("cannot open " + path);
  return objectHandle(id);
}

Handle File::openDataset(const std::string& path) const {
  if (!exists(path)) throw H5Error(name_ + ": no dataset " + path);
  hid_t id = H5Dopen2(file_.get(), path.c_str(), H5P_DEFAULT);
  if (id < 0) fail(path + " is not a dataset");
  return datasetHandle(id);
}

}  // namespace granwave::h5
