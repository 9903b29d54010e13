// The checked HDF5 calls and owning handles of the io package. (Length: one wrapper per HDF5
// object and call the package uses, all with the same error convention, naming the file.)
#include "Hdf5Support.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <utility>

#include <fcntl.h>
#include <unistd.h>

namespace capsula::io::hdf5 {

namespace {

using core::IoError;

std::string fileNameOf(hid_t object)
{
  const ssize_t size = H5Fget_name(object, nullptr, 0);
  if (size <= 0) {
    return "?";
  }
  std::string name(static_cast<std::size_t>(size) + 1, '\0');
  H5Fget_name(object, name.data(), name.size());
  name.resize(static_cast<std::size_t>(size));
  return name;
}

std::string objectPathOf(hid_t object)
{
  const ssize_t size = H5Iget_name(object, nullptr, 0);
  if (size <= 0) {
    return "/";
  }
  std::string name(static_cast<std::size_t>(size) + 1, '\0');
  H5Iget_name(object, name.data(), name.size());
  name.resize(static_cast<std::size_t>(size));
  return name;
}

/// "'/group/name' in 'file.h5'" for messages.
std::string where(hid_t parent, const std::string& name)
{
  std::string path = objectPathOf(parent);
  if (path.empty() || path.back() != '/') {
    path += '/';
  }
  return "'" + path + name + "' in '" + fileNameOf(parent) + "'";
}

// errno is cleared by ErrorSilencer, which every call wrapped here starts with, so a
// full disk seen now is this call's.
void check(bool ok, const std::string& what)
{
  if (!ok) {
    throw IoError("HDF5: cannot " + what + "." + core::diskFullAdvice(errno));
  }
}

Handle simpleSpace(const std::vector<hsize_t>& shape)
{
  Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr));
  check(space.get() >= 0, "create a dataspace");
  return space;
}

std::vector<hsize_t> shapeOf(hid_t space)
{
  const int rank = H5Sget_simple_extent_ndims(space);
  check(rank >= 0, "query a dataspace");
  std::vector<hsize_t> shape(static_cast<std::size_t>(rank));
  if (rank > 0) {
    H5Sget_simple_extent_dims(space, shape.data(), nullptr);
  }
  return shape;
}

hsize_t countOf(const std::vector<hsize_t>& shape)
{
  hsize_t n = 1;
  for (const hsize_t d : shape) {
    n *= d;
  }
  return n;
}

Handle creationOrderedGroupProperties()
{
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE));
  check(gcpl.get() >= 0, "create group properties");
  H5Pset_link_creation_order(gcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  H5Pset_attr_creation_order(gcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  return gcpl;
}

template <typename T>
void writeArray(hid_t parent, const std::string& name, const std::vector<T>& data, const std::vector<hsize_t>& shape,
                hid_t fileType, hid_t memoryType)
{
  ErrorSilencer quiet;
  if (countOf(shape) != data.size()) {
    throw core::Error(core::message("internal: dataset ", where(parent, name), " has ", data.size(),
                                    " values for shape of ", countOf(shape)));
  }
  Handle space = simpleSpace(shape);
  Handle set(H5Dcreate2(parent, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  check(set.get() >= 0, "create dataset " + where(parent, name));
  if (!data.empty()) {
    check(H5Dwrite(set.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) >= 0,
          "write dataset " + where(parent, name));
  }
}

template <typename T>
std::vector<T> readArray(hid_t parent, const std::string& name, std::vector<hsize_t>* shape, hid_t memoryType,
                         H5T_class_t expectedClass)
{
  ErrorSilencer quiet;
  Handle set(H5Dopen2(parent, name.c_str(), H5P_DEFAULT));
  check(set.get() >= 0, "open dataset " + where(parent, name));
  Handle type(H5Dget_type(set.get()));
  check(type.get() >= 0 && H5Tget_class(type.get()) == expectedClass,
        "read dataset " + where(parent, name) + ": it has the wrong type");
  Handle space(H5Dget_space(set.get()));
  const std::vector<hsize_t> dims = shapeOf(space.get());
  std::vector<T> data(static_cast<std::size_t>(countOf(dims)));
  if (!data.empty()) {
    check(H5Dread(set.get(), memoryType, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()) >= 0,
          "read dataset " + where(parent, name));
  }
  if (shape != nullptr) {
    *shape = dims;
  }
  return data;
}

Handle fixedStringType(std::size_t length)
{
  Handle type(H5Tcopy(H5T_C_S1));
  check(type.get() >= 0, "create a string type");
  // HDF5 has no zero-length fixed strings: an empty string is one padding byte.
  check(H5Tset_size(type.get(), length > 0 ? length : 1) >= 0, "size a string type");
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  return type;
}

std::string trimPadding(std::string text)
{
  while (!text.empty() && text.back() == '\0') {
    text.pop_back();
  }
  return text;
}

herr_t collectName(hid_t, const char* name, const H5L_info_t*, void* names)
{
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

herr_t collectAttributeName(hid_t, const char* name, const H5A_info_t*, void* names)
{
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

template <typename T>
void writeScalarAttribute(hid_t object, const std::string& name, const T& value, hid_t fileType, hid_t memoryType)
{
  ErrorSilencer quiet;
  Handle space(H5Screate(H5S_SCALAR));
  Handle attribute(H5Acreate2(object, name.c_str(), fileType, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  check(attribute.get() >= 0, "create attribute " + where(object, "@" + name));
  check(H5Awrite(attribute.get(), memoryType, &value) >= 0, "write attribute " + where(object, "@" + name));
}

Handle openAttribute(hid_t object, const std::string& name)
{
  Handle attribute(H5Aopen(object, name.c_str(), H5P_DEFAULT));
  check(attribute.get() >= 0, "find attribute " + where(object, "@" + name));
  return attribute;
}

} // namespace

Handle::~Handle()
{
  if (id_ >= 0) {
    ErrorSilencer quiet;
    switch (H5Iget_type(id_)) {
    case H5I_FILE:
      H5Fclose(id_);
      break;
    case H5I_GROUP:
      H5Gclose(id_);
      break;
    case H5I_DATASET:
      H5Dclose(id_);
      break;
    case H5I_DATASPACE:
      H5Sclose(id_);
      break;
    case H5I_DATATYPE:
      H5Tclose(id_);
      break;
    case H5I_ATTR:
      H5Aclose(id_);
      break;
    case H5I_GENPROP_LST:
      H5Pclose(id_);
      break;
    default:
      break;
    }
  }
}

Handle::Handle(Handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)) {}

Handle& Handle::operator=(Handle&& other) noexcept
{
  if (this != &other) {
    Handle old(std::exchange(id_, std::exchange(other.id_, H5I_INVALID_HID)));
  }
  return *this;
}

void Handle::close()
{
  if (id_ < 0) {
    return;
  }
  const hid_t id = std::exchange(id_, H5I_INVALID_HID);
  ErrorSilencer quiet;
  if (H5Iget_type(id) == H5I_FILE) {
    const std::string name = fileNameOf(id);
    check(H5Fclose(id) >= 0, "close (and flush) '" + name + "'");
  } else {
    Handle closing(id);
  }
}

ErrorSilencer::ErrorSilencer()
{
  H5Eget_auto2(H5E_DEFAULT, &function_, &data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  errno = 0;
}

ErrorSilencer::~ErrorSilencer()
{
  H5Eset_auto2(H5E_DEFAULT, function_, data_);
}

Handle createFile(const std::string& path, const std::string& role)
{
  ErrorSilencer quiet;
  Handle fcpl(H5Pcreate(H5P_FILE_CREATE));
  H5Pset_link_creation_order(fcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  H5Pset_attr_creation_order(fcpl.get(), H5P_CRT_ORDER_TRACKED | H5P_CRT_ORDER_INDEXED);
  Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, fcpl.get(), H5P_DEFAULT));
  if (file.get() < 0) {
    throw IoError("Cannot create the " + role + " file '" + path +
                  "' (is the directory writable and the disk not full?).");
  }
  return file;
}

Handle openFileForReading(const std::string& path, const std::string& role)
{
  ErrorSilencer quiet;
  if (!std::filesystem::exists(path)) {
    throw IoError("The " + role + " file '" + path + "' does not exist.");
  }
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    throw IoError("The " + role + " file '" + path + "' is not a readable HDF5 file (truncated or corrupt?).");
  }
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (file.get() < 0) {
    throw IoError("The " + role + " file '" + path + "' is truncated or corrupt (HDF5 cannot open it).");
  }
  return file;
}

void flush(hid_t object)
{
  ErrorSilencer quiet;
  check(H5Fflush(object, H5F_SCOPE_GLOBAL) >= 0, "flush '" + fileNameOf(object) + "'");
}

void copyObject(hid_t fromParent, const std::string& name, hid_t toParent)
{
  ErrorSilencer quiet;
  check(H5Ocopy(fromParent, name.c_str(), toParent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) >= 0,
        "copy " + where(fromParent, name) + " to '" + fileNameOf(toParent) + "'");
}

Handle createAnonymousGroup(hid_t object)
{
  ErrorSilencer quiet;
  Handle gcpl = creationOrderedGroupProperties();
  Handle group(H5Gcreate_anon(object, gcpl.get(), H5P_DEFAULT));
  check(group.get() >= 0, "create a group in '" + fileNameOf(object) + "'");
  return group;
}

void link(hid_t object, hid_t parent, const std::string& name)
{
  ErrorSilencer quiet;
  check(H5Olink(object, parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT) >= 0, "link " + where(parent, name));
}

void unlink(hid_t parent, const std::string& name)
{
  ErrorSilencer quiet;
  check(H5Ldelete(parent, name.c_str(), H5P_DEFAULT) >= 0, "remove " + where(parent, name));
}

Handle createGroup(hid_t parent, const std::string& name)
{
  ErrorSilencer quiet;
  Handle gcpl = creationOrderedGroupProperties();
  Handle group(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, gcpl.get(), H5P_DEFAULT));
  check(group.get() >= 0, "create group " + where(parent, name));
  return group;
}

Handle openGroup(hid_t parent, const std::string& name)
{
  ErrorSilencer quiet;
  Handle group(H5Gopen2(parent, name.c_str(), H5P_DEFAULT));
  check(group.get() >= 0, "open group " + where(parent, name));
  return group;
}

bool exists(hid_t parent, const std::string& name)
{
  ErrorSilencer quiet;
  return H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<std::string> memberNames(hid_t group)
{
  ErrorSilencer quiet;
  std::vector<std::string> names;
  if (H5Literate(group, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, collectName, &names) < 0) {
    names.clear(); // not written by us: no creation order, fall back to name order
    check(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectName, &names) >= 0,
          "list the members of '" + objectPathOf(group) + "' in '" + fileNameOf(group) + "'");
  }
  return names;
}

std::vector<std::string> attributeNames(hid_t object)
{
  ErrorSilencer quiet;
  std::vector<std::string> names;
  if (H5Aiterate2(object, H5_INDEX_CRT_ORDER, H5_ITER_INC, nullptr, collectAttributeName, &names) < 0) {
    names.clear();
    check(H5Aiterate2(object, H5_INDEX_NAME, H5_ITER_INC, nullptr, collectAttributeName, &names) >= 0,
          "list the attributes of '" + objectPathOf(object) + "' in '" + fileNameOf(object) + "'");
  }
  return names;
}

void writeDoubles(hid_t parent, const std::string& name, const std::vector<double>& data,
                  const std::vector<hsize_t>& shape)
{
  writeArray(parent, name, data, shape, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

void writeIntegers(hid_t parent, const std::string& name, const std::vector<std::int64_t>& data,
                   const std::vector<hsize_t>& shape)
{
  writeArray(parent, name, data, shape, H5T_STD_I64LE, H5T_NATIVE_INT64);
}

std::vector<hsize_t> datasetShape(hid_t parent, const std::string& name)
{
  ErrorSilencer quiet;
  Handle set(H5Dopen2(parent, name.c_str(), H5P_DEFAULT));
  check(set.get() >= 0, "open dataset " + where(parent, name));
  Handle space(H5Dget_space(set.get()));
  check(space.get() >= 0, "query dataset " + where(parent, name));
  return shapeOf(space.get());
}

std::vector<double> readDoubles(hid_t parent, const std::string& name, std::vector<hsize_t>* shape)
{
  return readArray<double>(parent, name, shape, H5T_NATIVE_DOUBLE, H5T_FLOAT);
}

std::vector<std::int64_t> readIntegers(hid_t parent, const std::string& name, std::vector<hsize_t>* shape)
{
  return readArray<std::int64_t>(parent, name, shape, H5T_NATIVE_INT64, H5T_INTEGER);
}

void writeString(hid_t parent, const std::string& name, const std::string& text)
{
  ErrorSilencer quiet;
  Handle type = fixedStringType(text.size());
  Handle space(H5Screate(H5S_SCALAR));
  Handle set(H5Dcreate2(parent, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  check(set.get() >= 0, "create dataset " + where(parent, name));
  std::string padded = text;
  padded.resize(text.empty() ? 1 : text.size(), '\0');
  check(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, padded.data()) >= 0,
        "write dataset " + where(parent, name));
}

std::string readString(hid_t parent, const std::string& name)
{
  ErrorSilencer quiet;
  Handle set(H5Dopen2(parent, name.c_str(), H5P_DEFAULT));
  check(set.get() >= 0, "open dataset " + where(parent, name));
  Handle type(H5Dget_type(set.get()));
  check(H5Tget_class(type.get()) == H5T_STRING && H5Tis_variable_str(type.get()) == 0,
        "read dataset " + where(parent, name) + ": it is not a fixed-length string");
  std::string text(H5Tget_size(type.get()), '\0');
  check(H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) >= 0,
        "read dataset " + where(parent, name));
  return trimPadding(std::move(text));
}

void writeAttribute(hid_t object, const std::string& name, double value)
{
  writeScalarAttribute(object, name, value, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

void writeAttribute(hid_t object, const std::string& name, std::int64_t value)
{
  writeScalarAttribute(object, name, value, H5T_STD_I64LE, H5T_NATIVE_INT64);
}

void writeAttribute(hid_t object, const std::string& name, const std::string& value)
{
  ErrorSilencer quiet;
  Handle type = fixedStringType(value.size());
  Handle space(H5Screate(H5S_SCALAR));
  Handle attribute(H5Acreate2(object, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT));
  check(attribute.get() >= 0, "create attribute " + where(object, "@" + name));
  std::string padded = value;
  padded.resize(value.empty() ? 1 : value.size(), '\0');
  check(H5Awrite(attribute.get(), type.get(), padded.data()) >= 0, "write attribute " + where(object, "@" + name));
}

void writeAttribute(hid_t object, const std::string& name, const std::vector<std::int64_t>& values)
{
  ErrorSilencer quiet;
  Handle space = simpleSpace({static_cast<hsize_t>(values.size())});
  Handle attribute(H5Acreate2(object, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  check(attribute.get() >= 0, "create attribute " + where(object, "@" + name));
  check(H5Awrite(attribute.get(), H5T_NATIVE_INT64, values.data()) >= 0,
        "write attribute " + where(object, "@" + name));
}

double readDoubleAttribute(hid_t object, const std::string& name)
{
  ErrorSilencer quiet;
  Handle attribute = openAttribute(object, name);
  Handle space(H5Aget_space(attribute.get()));
  check(H5Sget_simple_extent_npoints(space.get()) == 1, "read attribute " + where(object, "@" + name));
  double value = 0.0;
  check(H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &value) >= 0, "read attribute " + where(object, "@" + name));
  return value;
}

std::int64_t readIntegerAttribute(hid_t object, const std::string& name)
{
  ErrorSilencer quiet;
  Handle attribute = openAttribute(object, name);
  Handle space(H5Aget_space(attribute.get()));
  check(H5Sget_simple_extent_npoints(space.get()) == 1, "read attribute " + where(object, "@" + name));
  std::int64_t value = 0;
  check(H5Aread(attribute.get(), H5T_NATIVE_INT64, &value) >= 0, "read attribute " + where(object, "@" + name));
  return value;
}

std::string readStringAttribute(hid_t object, const std::string& name)
{
  ErrorSilencer quiet;
  Handle attribute = openAttribute(object, name);
  Handle type(H5Aget_type(attribute.get()));
  check(H5Tget_class(type.get()) == H5T_STRING && H5Tis_variable_str(type.get()) == 0,
        "read attribute " + where(object, "@" + name) + ": it is not a fixed-length string");
  std::string text(H5Tget_size(type.get()), '\0');
  check(H5Aread(attribute.get(), type.get(), text.data()) >= 0, "read attribute " + where(object, "@" + name));
  return trimPadding(std::move(text));
}

std::vector<std::int64_t> readIntegerArrayAttribute(hid_t object, const std::string& name)
{
  ErrorSilencer quiet;
  Handle attribute = openAttribute(object, name);
  Handle space(H5Aget_space(attribute.get()));
  const hssize_t n = H5Sget_simple_extent_npoints(space.get());
  check(n >= 0, "read attribute " + where(object, "@" + name));
  std::vector<std::int64_t> values(static_cast<std::size_t>(n));
  if (n > 0) {
    check(H5Aread(attribute.get(), H5T_NATIVE_INT64, values.data()) >= 0,
          "read attribute " + where(object, "@" + name));
  }
  return values;
}

bool hasAttribute(hid_t object, const std::string& name)
{
  ErrorSilencer quiet;
  return H5Aexists(object, name.c_str()) > 0;
}

void syncToDisk(const std::string& path)
{
  const int fd = ::open(path.c_str(), O_RDONLY);
  if (fd < 0 || ::fsync(fd) != 0) {
    const int error = errno;
    const std::string why = std::strerror(error);
    if (fd >= 0) {
      ::close(fd);
    }
    throw IoError("Cannot flush '" + path + "' to disk: " + why + "." + core::diskFullAdvice(error));
  }
  ::close(fd);
}

} // namespace capsula::io::hdf5
