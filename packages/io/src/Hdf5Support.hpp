#pragma once
// Private helpers over the HDF5 C API: an owning handle, and typed reads and writes of
// whole datasets and attributes. Every failure throws core::IoError naming the file and
// the object; HDF5's own error printing is silenced while these run.
//
// Files are opened with the default (POSIX, serial) driver even though the library is
// the parallel build: Capsula gathers output data to one rank, which writes alone.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace capsula::io::hdf5 {

/// Owns an HDF5 identifier of any kind and closes it with the matching H5*close.
class Handle {
public:
  Handle() = default;
  explicit Handle(hid_t id) : id_(id) {}
  ~Handle();
  Handle(Handle&& other) noexcept;
  Handle& operator=(Handle&& other) noexcept;
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  /// Closes now; throws IoError if closing fails (a file close flushes data).
  void close();

private:
  hid_t id_ = H5I_INVALID_HID;
};

/// Silences HDF5's automatic error printing for its lifetime.
class ErrorSilencer {
public:
  ErrorSilencer();
  ~ErrorSilencer();
  ErrorSilencer(const ErrorSilencer&) = delete;
  ErrorSilencer& operator=(const ErrorSilencer&) = delete;

private:
  H5E_auto2_t function_ = nullptr;
  void* data_ = nullptr;
};

/// A new file (replacing any), or an existing one for reading; `role` names the file in
/// messages ("checkpoint", "snapshot").
Handle createFile(const std::string& path, const std::string& role);
Handle openFileForReading(const std::string& path, const std::string& role);
/// Writes everything HDF5 holds in memory for the file of `object` to it.
void flush(hid_t object);

/// Groups track the creation order of their members, so listings keep the write order.
Handle createGroup(hid_t parent, const std::string& name);
Handle openGroup(hid_t parent, const std::string& name);
/// A group in the file of `object` that no path reaches yet; link() makes it visible. An
/// anonymous group that is closed unlinked is dropped, so a group filled and linked last
/// appears whole or not at all.
Handle createAnonymousGroup(hid_t object);
void link(hid_t object, hid_t parent, const std::string& name);
/// Copies the object `name` of `fromParent` (a group with all it holds) to `toParent`, in
/// the same or another file.
void copyObject(hid_t fromParent, const std::string& name, hid_t toParent);
/// Removes the link `name` from `parent` (the object goes when nothing links to it).
void unlink(hid_t parent, const std::string& name);
bool exists(hid_t parent, const std::string& name);
/// Names of the members of a group, in creation order.
std::vector<std::string> memberNames(hid_t group);
/// Names of the attributes of an object, in creation order.
std::vector<std::string> attributeNames(hid_t object);

void writeDoubles(hid_t parent, const std::string& name, const std::vector<double>& data,
                  const std::vector<hsize_t>& shape);
void writeIntegers(hid_t parent, const std::string& name, const std::vector<std::int64_t>& data,
                   const std::vector<hsize_t>& shape);
void writeString(hid_t parent, const std::string& name, const std::string& text);

/// The shape of a dataset, without reading it.
std::vector<hsize_t> datasetShape(hid_t parent, const std::string& name);

std::vector<double> readDoubles(hid_t parent, const std::string& name, std::vector<hsize_t>* shape);
std::vector<std::int64_t> readIntegers(hid_t parent, const std::string& name, std::vector<hsize_t>* shape);
std::string readString(hid_t parent, const std::string& name);

void writeAttribute(hid_t object, const std::string& name, double value);
void writeAttribute(hid_t object, const std::string& name, std::int64_t value);
void writeAttribute(hid_t object, const std::string& name, const std::string& value);
void writeAttribute(hid_t object, const std::string& name, const std::vector<std::int64_t>& values);

double readDoubleAttribute(hid_t object, const std::string& name);
std::int64_t readIntegerAttribute(hid_t object, const std::string& name);
std::string readStringAttribute(hid_t object, const std::string& name);
std::vector<std::int64_t> readIntegerArrayAttribute(hid_t object, const std::string& name);
bool hasAttribute(hid_t object, const std::string& name);

/// Forces a finished file's data to disk (fsync), so that a rename over the previous
/// version is durable even across a machine crash.
void syncToDisk(const std::string& path);

} // namespace capsula::io::hdf5
