#include "capsula/io/CheckpointSection.hpp"

#include "capsula/core/Error.hpp"

namespace capsula::io {

namespace {

template <typename Map>
const typename Map::mapped_type& entry(const Map& map, const std::string& name, const char* kind,
                                       const std::string& source)
{
  const auto it = map.find(name);
  core::require<core::InputError>(it != map.end(), "The checkpoint '", source, "' lacks the ", kind, " '", name,
                                  "': it was written by another application or another version of Capsula. "
                                  "Start the run again without --restart.");
  return it->second;
}

} // namespace

void saveSections(Checkpoint& checkpoint, const std::vector<const CheckpointSection*>& sections)
{
  for (const auto* section : sections) {
    section->save(checkpoint);
  }
}

void loadSections(const Checkpoint& checkpoint, const std::string& source,
                  const std::vector<CheckpointSection*>& sections)
{
  for (auto* section : sections) {
    section->load(checkpoint, source);
  }
}

double requiredReal(const Checkpoint& checkpoint, const std::string& name, const std::string& source)
{
  return entry(checkpoint.reals, name, "value", source);
}

std::int64_t requiredInteger(const Checkpoint& checkpoint, const std::string& name, const std::string& source)
{
  return entry(checkpoint.integers, name, "integer", source);
}

const std::vector<double>& requiredArray(const Checkpoint& checkpoint, const std::string& name,
                                         const std::string& source)
{
  return entry(checkpoint.arrays, name, "array", source);
}

const std::vector<double>* optionalArray(const Checkpoint& checkpoint, const std::string& name)
{
  const auto it = checkpoint.arrays.find(name);
  return it == checkpoint.arrays.end() ? nullptr : &it->second;
}

} // namespace capsula::io
