#include "h5/Strings.hpp"

#include <cstring>

#include "h5/ErrorStack.hpp"
#include "h5/H5Error.hpp"

namespace granwave::h5 {
namespace {

std::vector<std::string> readVariableLength(hid_t stored_type, std::size_t count,
                                            const std::function<herr_t(hid_t, void*)>& read,
                                            const std::string& file, const std::string& what) {
  Handle memory = datatypeHandle(check(H5Tcopy(H5T_C_S1), file, "cannot copy string type"));
  check(H5Tset_size(memory.get(), H5T_VARIABLE), file, "cannot size string type");
  check(H5Tset_cset(memory.get(), H5Tget_cset(stored_type)), file, "cannot set string cset");
  std::vector<char*> buffer(count, nullptr);
  if (read(memory.get(), buffer.data()) < 0) fail(file, "cannot read " + what);
  std::vector<std::string> strings;
  strings.reserve(count);
  for (char* s : buffer) {
    strings.emplace_back(s != nullptr ? s : "");
    H5free_memory(s);  // HDF5 allocated each string; it must free them too
  }
  return strings;
}

std::vector<std::string> readFixedLength(hid_t stored_type, std::size_t count,
                                         const std::function<herr_t(hid_t, void*)>& read,
                                         const std::string& file, const std::string& what) {
  // Read the bytes as stored and cut each at its first NUL: works for null-terminated and
  // null-padded strings alike, including one that fills its whole width.
  const std::size_t width = H5Tget_size(stored_type);
  Handle memory = datatypeHandle(check(H5Tcopy(stored_type), file, "cannot copy string type"));
  std::vector<char> buffer(count * width + 1, '\0');
  if (read(memory.get(), buffer.data()) < 0) fail(file, "cannot read " + what);
  const bool space_padded = H5Tget_strpad(stored_type) == H5T_STR_SPACEPAD;
  std::vector<std::string> strings;
  strings.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    const char* begin = buffer.data() + i * width;
    std::string s(begin, strnlen(begin, width));
    if (space_padded) s.erase(s.find_last_not_of(' ') + 1);
    strings.push_back(std::move(s));
  }
  return strings;
}

}  // namespace

Handle utf8StringType(const std::string& file) {
  Handle type = datatypeHandle(check(H5Tcopy(H5T_C_S1), file, "cannot copy string type"));
  check(H5Tset_size(type.get(), H5T_VARIABLE), file, "cannot size string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), file, "cannot set string cset");
  return type;
}

std::vector<std::string> readStrings(hid_t stored_type, std::size_t count,
                                     const std::function<herr_t(hid_t, void*)>& read,
                                     const std::string& file, const std::string& what) {
  if (H5Tget_class(stored_type) != H5T_STRING) throw H5Error(file + ": " + what + " is not text");
  const htri_t variable = H5Tis_variable_str(stored_type);
  if (variable < 0) fail(file, "cannot inspect the string type of " + what);
  return variable > 0 ? readVariableLength(stored_type, count, read, file, what)
                      : readFixedLength(stored_type, count, read, file, what);
}

}  // namespace granwave::h5
