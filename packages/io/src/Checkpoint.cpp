#include "capsula/io/Checkpoint.hpp"

#include "Hdf5Support.hpp"

#include "capsula/core/Error.hpp"
#include "capsula/core/Files.hpp"

#include <cstdio>

namespace capsula::io {

namespace {

constexpr const char* checkpointFormatName = "Capsula checkpoint";
constexpr std::int64_t checkpointFormatVersion = 1;

template <typename Map>
void checkNames(const Map& map, const char* kind, const std::string& path)
{
  for (const auto& entry : map) {
    core::require<core::IoError>(
        !entry.first.empty() && entry.first.find('/') == std::string::npos && entry.first != ".",
        "Cannot write checkpoint '", path, "': the ", kind, " name '", entry.first, "' is empty or contains '/'.");
  }
}

} // namespace

void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint)
{
  checkNames(checkpoint.arrays, "array", path);
  checkNames(checkpoint.reals, "real", path);
  checkNames(checkpoint.integers, "integer", path);
  const std::string temporary = core::temporaryPathFor(path);
  try {
    hdf5::Handle file = hdf5::createFile(temporary, "checkpoint");
    hdf5::writeAttribute(file.get(), "format", std::string(checkpointFormatName));
    hdf5::writeAttribute(file.get(), "version", checkpointFormatVersion);
    hdf5::writeAttribute(file.get(), "time", checkpoint.time);
    hdf5::writeAttribute(file.get(), "step", checkpoint.step);
    hdf5::writeAttribute(file.get(), "step size", checkpoint.stepSize);
    if (!checkpoint.application.empty()) {
      hdf5::writeAttribute(file.get(), "application", checkpoint.application);
    }
    hdf5::writeString(file.get(), "deck", checkpoint.deckXml);
    hdf5::Handle arrays = hdf5::createGroup(file.get(), "arrays");
    for (const auto& [name, values] : checkpoint.arrays) {
      hdf5::writeDoubles(arrays.get(), name, values, {static_cast<hsize_t>(values.size())});
    }
    hdf5::Handle reals = hdf5::createGroup(file.get(), "reals");
    for (const auto& [name, value] : checkpoint.reals) {
      hdf5::writeAttribute(reals.get(), name, value);
    }
    hdf5::Handle integers = hdf5::createGroup(file.get(), "integers");
    for (const auto& [name, value] : checkpoint.integers) {
      hdf5::writeAttribute(integers.get(), name, value);
    }
    arrays.close();
    reals.close();
    integers.close();
    file.close();
    hdf5::syncToDisk(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  core::replaceFileAtomically(temporary, path);
}

Checkpoint readCheckpoint(const std::string& path)
{
  hdf5::Handle file = hdf5::openFileForReading(path, "checkpoint");
  const bool ours = hdf5::hasAttribute(file.get(), "format") &&
                    hdf5::readStringAttribute(file.get(), "format") == checkpointFormatName;
  core::require<core::IoError>(ours, "'", path, "' is an HDF5 file but not a Capsula checkpoint.");
  const std::int64_t version = hdf5::readIntegerAttribute(file.get(), "version");
  core::require<core::IoError>(version == checkpointFormatVersion, "Checkpoint '", path, "' has format version ",
                               version, "; this Capsula reads version ", checkpointFormatVersion, ".");
  try {
    Checkpoint c;
    c.time = hdf5::readDoubleAttribute(file.get(), "time");
    c.step = hdf5::readIntegerAttribute(file.get(), "step");
    c.stepSize = hdf5::readDoubleAttribute(file.get(), "step size");
    if (hdf5::hasAttribute(file.get(), "application")) {
      c.application = hdf5::readStringAttribute(file.get(), "application");
    }
    c.deckXml = hdf5::readString(file.get(), "deck");
    hdf5::Handle arrays = hdf5::openGroup(file.get(), "arrays");
    for (const auto& name : hdf5::memberNames(arrays.get())) {
      std::vector<hsize_t> shape;
      c.arrays[name] = hdf5::readDoubles(arrays.get(), name, &shape);
      core::require<core::IoError>(shape.size() == 1, "array '", name, "' is not a vector");
    }
    hdf5::Handle reals = hdf5::openGroup(file.get(), "reals");
    for (const auto& name : hdf5::attributeNames(reals.get())) {
      c.reals[name] = hdf5::readDoubleAttribute(reals.get(), name);
    }
    hdf5::Handle integers = hdf5::openGroup(file.get(), "integers");
    for (const auto& name : hdf5::attributeNames(integers.get())) {
      c.integers[name] = hdf5::readIntegerAttribute(integers.get(), name);
    }
    return c;
  } catch (const core::IoError& e) {
    throw core::IoError("Checkpoint '" + path + "' is incomplete or corrupt: " + e.what());
  }
}

} // namespace capsula::io
