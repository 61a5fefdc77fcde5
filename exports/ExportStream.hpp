#pragma once
// The output stream of a text or binary export: a failed write (a full disk, a removed
// directory) becomes a std::system_error naming the published file, not a silent short file.
#include <fstream>
#include <string>

namespace granwave {

class ExportStream {
 public:
  ExportStream(const std::string& path, std::string target, bool binary);
  std::ofstream& out() { return out_; }
  // std::system_error naming the target if any write so far failed.
  void check() const;
  // Flushes and closes the file, then check().
  void close();

 private:
  std::ofstream out_;
  std::string target_;
};

}  // namespace granwave
