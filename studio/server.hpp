#pragma once
// The studio's web server (civetweb, Debian's libcivetweb-dev): the page's
// files from web/dist over HTTP and one WebSocket, /ws, per open tab. Text
// messages in are commands (JSON); messages out are JSON replies and status,
// and binary topologies and frames (frames.hpp). One sender thread writes
// every outgoing message, so each tab gets them in order, at its own rate.
//
// Safety: it listens on 127.0.0.1 unless a host is given; with a host, the
// WebSocket and the page need the random token of the printed URL. Only
// commands the session defines reach it; a message that is not JSON, too
// large, binary or unknown gets an error reply and the server goes on.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "session.hpp"

struct mg_context;
struct mg_connection;

namespace tendril::studio {

struct ServerOptions {
  std::string host = "127.0.0.1";
  int port = 8765;  // 0: any free port
  std::string web_dir;
  bool token = false;  // require the URL's random token (always for an address other than loopback's)
  std::size_t max_message = 64 * 1024;
  double max_rate = 120;  // frames per second a tab may ask for
};

class Server : public Outbox {
 public:
  using Handler = std::function<void(ClientId, json)>;
  Server(ServerOptions options, Handler on_command, std::function<bool(const std::string&)> is_command);
  ~Server() override;
  std::string url() const;  // what to open, with the token when one is needed
  int port() const { return port_; }

  void frame(std::shared_ptr<const std::string> bytes, bool urgent,
             std::shared_ptr<const std::string> topology = nullptr) override;
  void send(ClientId to, const std::string& bytes, bool binary) override;
  void broadcast(const std::string& text) override;
  bool wants_frame() const override;

 private:
  struct Message {
    std::shared_ptr<const std::string> bytes;
    bool binary;
  };
  struct Client {
    mg_connection* conn = nullptr;
    double rate = 0;  // frames per second asked; 0 until the page says
    bool ready = true;  // it took the last frame it was sent ("ready")
    std::chrono::steady_clock::time_point next_frame{};
    std::uint64_t topology_sent = 0, frame_sent = 0;  // sequence numbers of what it has
    std::deque<Message> queue;
    std::string partial;  // a fragmented message being put together
    // Held while the sender writes; the close handler takes it before it
    // returns (civetweb frees the connection after), and marks it closed.
    std::mutex writing;
    bool closed = false;
  };
  static int on_connect(const mg_connection* conn, void* self);
  static void on_ready(mg_connection* conn, void* self);
  static int on_data(mg_connection* conn, int flags, char* data, std::size_t size, void* self);
  static void on_close(const mg_connection* conn, void* self);
  static int on_index(mg_connection* conn, void* self);
  void receive(ClientId id, const std::string& text);
  void reply_error(ClientId id, const std::string& message);
  void sender();
  void update_wants();  // under mutex_: when the next frame is due
  bool token_ok(const char* query) const;

  ServerOptions options_;
  Handler on_command_;
  std::function<bool(const std::string&)> is_command_;
  std::string token_;
  mg_context* ctx_ = nullptr;
  int port_ = 0;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::map<ClientId, std::shared_ptr<Client>> clients_;
  std::map<const mg_connection*, ClientId> ids_;
  ClientId next_id_ = 1;
  std::shared_ptr<const std::string> topology_, frame_;
  std::uint64_t topology_seq_ = 0, frame_seq_ = 0;
  bool frame_urgent_ = false;
  // The earliest time a tab is due a frame (steady clock ns; max: none):
  // the solver thread reads it after every step without a lock.
  std::atomic<std::int64_t> frame_due_{std::numeric_limits<std::int64_t>::max()};
  bool stopping_ = false;
  std::uint64_t news_ = 0;  // counts what the sender has to look at
  std::thread sender_;
};

}  // namespace tendril::studio
