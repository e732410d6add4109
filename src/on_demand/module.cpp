// The module's side: the entry the program looks up, over the server and the zip writer.
#include "export/zip_archive.hpp"
#include "on_demand/on_demand.hpp"

namespace wobble::on_demand {
namespace {
class ServerService final : public Service {
 public:
  explicit ServerService(serve::ServeOptions options) : server_(std::move(options)) {}
  int bind() override { return server_.bind(); }
  void run() override { server_.run(); }
  void stop() override { server_.stop(); }
  const std::string& token() const override { return server_.token(); }

 private:
  serve::Server server_;
};

std::unique_ptr<Service> make_server(serve::ServeOptions options) {
  return std::make_unique<ServerService>(std::move(options));
}
}  // namespace
}  // namespace wobble::on_demand

extern "C" const wobble::on_demand::Entry* wobble_on_demand_entry() {
  static const wobble::on_demand::Entry entry{WOBBLE_VERSION, &wobble::on_demand::make_server,
                                              &wobble::exports::zip_archive};
  return &entry;
}
