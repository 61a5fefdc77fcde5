// File: attributes of groups and datasets (numbers, number arrays, strings, string arrays).
#include <cstdint>

#include "h5/Dataspace.hpp"
#include "h5/ErrorStack.hpp"
#include "h5/File.hpp"
#include "h5/H5Error.hpp"
#include "h5/Strings.hpp"

namespace granwave::h5 {
namespace {

std::string attributeLabel(const std::string& object, const std::string& name) {
  return "attribute " + name + " of " + object;
}

}  // namespace

void File::writeRawAttribute(const std::string& object, const std::string& name, hid_t file_type,
                             hid_t memory_type, const Shape& shape, const void* data) {
  Handle target = openObject(object);
  const std::string label = attributeLabel(object, name);
  const htri_t present = H5Aexists(target.get(), name.c_str());
  if (present < 0) fail("cannot inspect " + label);
  if (present > 0 && H5Adelete(target.get(), name.c_str()) < 0) fail("cannot replace " + label);
  Handle space = makeDataspace(shape, name_);
  hid_t id =
      H5Acreate2(target.get(), name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT);
  Handle attribute = attributeHandle(check(id, name_, "cannot create " + label));
  if (H5Awrite(attribute.get(), memory_type, data) < 0) fail("cannot write " + label);
}

template <Element T>
void File::writeAttribute(const std::string& object, const std::string& name, T value) {
  writeRawAttribute(object, name, fileType<T>(), nativeType<T>(), {}, &value);
}

template <Element T>
void File::writeArrayAttribute(const std::string& object, const std::string& name,
                               const std::vector<T>& values) {
  writeRawAttribute(object, name, fileType<T>(), nativeType<T>(), {values.size()}, values.data());
}

void File::writeStringAttribute(const std::string& object, const std::string& name,
                                const std::string& value) {
  Handle type = utf8StringType(name_);
  const char* data = value.c_str();
  writeRawAttribute(object, name, type.get(), type.get(), {}, &data);
}

void File::writeStringArrayAttribute(const std::string& object, const std::string& name,
                                     const std::vector<std::string>& values) {
  Handle type = utf8StringType(name_);
  std::vector<const char*> data;
  for (const std::string& value : values) data.push_back(value.c_str());
  writeRawAttribute(object, name, type.get(), type.get(), {values.size()}, data.data());
}

bool File::hasAttribute(const std::string& object, const std::string& name) const {
  if (!exists(object)) return false;
  Handle target = openObject(object);
  return H5Aexists(target.get(), name.c_str()) > 0;
}

Handle File::openAttribute(const std::string& object, const std::string& name) const {
  if (!hasAttribute(object, name)) throw H5Error(name_ + ": no " + attributeLabel(object, name));
  hid_t id = H5Aopen_by_name(file_.get(), object.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT);
  return attributeHandle(check(id, name_, "cannot open " + attributeLabel(object, name)));
}

template <Element T>
std::vector<T> File::readNumericAttribute(const std::string& object,
                                          const std::string& name) const {
  const std::string label = attributeLabel(object, name);
  Handle attribute = openAttribute(object, name);
  Handle type = datatypeHandle(check(H5Aget_type(attribute.get()), name_, "no type"));
  const H5T_class_t kind = H5Tget_class(type.get());
  if (kind != H5T_INTEGER && kind != H5T_FLOAT)
    throw H5Error(name_ + ": " + label + " is not numeric");
  Handle space = dataspaceHandle(check(H5Aget_space(attribute.get()), name_, "no dataspace"));
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0) fail("cannot size " + label);
  std::vector<T> values(static_cast<std::size_t>(count));
  if (H5Aread(attribute.get(), nativeType<T>(), values.data()) < 0) fail("cannot read " + label);
  return values;
}

template <Element T>
T File::readAttribute(const std::string& object, const std::string& name) const {
  std::vector<T> values = readNumericAttribute<T>(object, name);
  if (values.size() != 1) {
    throw H5Error(name_ + ": " + attributeLabel(object, name) + " holds " +
                  std::to_string(values.size()) + " values, expected one");
  }
  return values.front();
}

template <Element T>
std::vector<T> File::readArrayAttribute(const std::string& object, const std::string& name) const {
  return readNumericAttribute<T>(object, name);
}

std::vector<std::string> File::readStringArrayAttribute(const std::string& object,
                                                        const std::string& name) const {
  const std::string label = attributeLabel(object, name);
  Handle attribute = openAttribute(object, name);
  Handle type = datatypeHandle(check(H5Aget_type(attribute.get()), name_, "no type"));
  Handle space = dataspaceHandle(check(H5Aget_space(attribute.get()), name_, "no dataspace"));
  const hssize_t count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0) fail("cannot size " + label);
  auto read = [&](hid_t memory, void* buffer) { return H5Aread(attribute.get(), memory, buffer); };
  return readStrings(type.get(), static_cast<std::size_t>(count), read, name_, label);
}

std::string File::readStringAttribute(const std::string& object, const std::string& name) const {
  std::vector<std::string> values = readStringArrayAttribute(object, name);
  if (values.size() != 1) {
    throw H5Error(name_ + ": " + attributeLabel(object, name) + " holds " +
                  std::to_string(values.size()) + " strings, expected one");
  }
  return values.front();
}

#define GRANWAVE_H5_ATTRIBUTES(T)                                                    \
  template void File::writeAttribute<T>(const std::string&, const std::string&, T);  \
  template void File::writeArrayAttribute<T>(const std::string&, const std::string&, \
                                             const std::vector<T>&);                 \
  template T File::readAttribute<T>(const std::string&, const std::string&) const;   \
  template std::vector<T> File::readArrayAttribute<T>(const std::string&, const std::string&) const;
GRANWAVE_H5_ATTRIBUTES(double)
GRANWAVE_H5_ATTRIBUTES(std::int64_t)
GRANWAVE_H5_ATTRIBUTES(std::uint64_t)
#undef GRANWAVE_H5_ATTRIBUTES

}  // namespace granwave::h5
