#include "server.hpp"

#include <civetweb.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <stdexcept>
#include <vector>

namespace tendril::studio {

namespace {

std::string random_token() {
  std::random_device rd;  // the OS's entropy: a token nobody can guess from the seed of a scene
  std::string out;
  const char* hex = "0123456789abcdef";
  for (int k = 0; k < 32; ++k) out += hex[rd() % 16];
  return out;
}

std::string query_value(const char* query, const char* key) {
  if (!query) return {};
  char buf[128];
  const int n = mg_get_var(query, std::strlen(query), key, buf, sizeof buf);
  return n > 0 ? std::string(buf, std::size_t(n)) : std::string();
}

Server* self_of(void* p) { return static_cast<Server*>(p); }

}  // namespace

Server::Server(ServerOptions options, Handler on_command, std::function<bool(const std::string&)> is_command)
    : options_(std::move(options)), on_command_(std::move(on_command)), is_command_(std::move(is_command)) {
  if (options_.host != "127.0.0.1" && options_.host != "localhost") options_.token = true;
  if (options_.token) token_ = random_token();
  if (!std::filesystem::exists(options_.web_dir + "/index.html"))
    throw std::runtime_error("the studio page is not built (" + options_.web_dir +
                             "/index.html is missing): run `bash tools/setup.sh`");
  const std::string listen = options_.host + ":" + std::to_string(options_.port);
  const char* config[] = {"listening_ports", listen.c_str(), "document_root", options_.web_dir.c_str(),
                          "num_threads", "16", "enable_directory_listing", "no",
                          "websocket_timeout_ms", "3600000", "access_control_allow_origin", "",
                          // Frames go out as soon as written: with Nagle's algorithm a small
                          // message waits for the page's delayed ACK (40 ms) behind the last.
                          "tcp_nodelay", "1", nullptr};
  mg_init_library(0);
  mg_callbacks callbacks{};
  callbacks.log_message = [](const mg_connection*, const char*) { return 1; };  // errors go to replies, not stdout
  ctx_ = mg_start(&callbacks, this, config);
  if (!ctx_) throw std::runtime_error("cannot listen on " + listen + " (is the port taken? try --port 0)");
  mg_server_port ports[4];
  if (mg_get_server_ports(ctx_, 4, ports) > 0) port_ = ports[0].port;
  mg_set_request_handler(ctx_, "/$", on_index, this);
  mg_set_request_handler(ctx_, "/index.html$", on_index, this);
  mg_set_websocket_handler(ctx_, "/ws", on_connect, on_ready, on_data, on_close, this);
  sender_ = std::thread([this] { sender(); });
}

Server::~Server() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (sender_.joinable()) sender_.join();
  if (ctx_) mg_stop(ctx_);
  mg_exit_library();
}

std::string Server::url() const {
  std::string host = options_.host == "0.0.0.0" ? "127.0.0.1" : options_.host;
  std::string u = "http://" + host + ":" + std::to_string(port_) + "/";
  if (options_.token) u += "?token=" + token_;
  return u;
}

bool Server::token_ok(const char* query) const {
  if (!options_.token) return true;
  const std::string given = query_value(query, "token");
  if (given.size() != token_.size()) return false;
  unsigned char diff = 0;  // the same time for every wrong token
  for (std::size_t k = 0; k < given.size(); ++k) diff |= static_cast<unsigned char>(given[k] ^ token_[k]);
  return diff == 0;
}

int Server::on_index(mg_connection* conn, void* self) {
  Server& s = *self_of(self);
  if (!s.token_ok(mg_get_request_info(conn)->query_string)) {
    mg_send_http_error(conn, 403, "%s", "tendril studio: this page needs the token of the URL the studio printed");
    return 403;
  }
  mg_send_file(conn, (s.options_.web_dir + "/index.html").c_str());
  return 200;
}

int Server::on_connect(const mg_connection* conn, void* self) {
  return self_of(self)->token_ok(mg_get_request_info(conn)->query_string) ? 0 : 1;  // 0 accepts
}

void Server::on_ready(mg_connection* conn, void* self) {
  Server& s = *self_of(self);
  std::lock_guard<std::mutex> lock(s.mutex_);
  const ClientId id = s.next_id_++;
  auto c = std::make_shared<Client>();
  c->conn = conn;
  s.clients_[id] = c;
  s.ids_[conn] = id;
}

void Server::on_close(const mg_connection* conn, void* self) {
  Server& s = *self_of(self);
  std::shared_ptr<Client> c;
  {
    std::lock_guard<std::mutex> lock(s.mutex_);
    auto it = s.ids_.find(conn);
    if (it == s.ids_.end()) return;
    c = s.clients_[it->second];
    s.clients_.erase(it->second);
    s.ids_.erase(it);
    s.update_wants();
  }
  std::lock_guard<std::mutex> writing(c->writing);  // a write in progress finishes first
  c->closed = true;
}

int Server::on_data(mg_connection* conn, int flags, char* data, std::size_t size, void* self) {
  Server& s = *self_of(self);
  const int opcode = flags & 0x0f;
  const bool fin = flags & 0x80;
  if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) return 0;
  if (opcode == MG_WEBSOCKET_OPCODE_PING || opcode == MG_WEBSOCKET_OPCODE_PONG) return 1;
  ClientId id = 0;
  std::string text;
  bool binary = false, oversized = false;
  {
    std::lock_guard<std::mutex> lock(s.mutex_);
    auto it = s.ids_.find(conn);
    if (it == s.ids_.end()) return 1;
    id = it->second;
    Client& c = *s.clients_[id];
    if (opcode == MG_WEBSOCKET_OPCODE_BINARY) binary = true;
    if (c.partial.size() + size > s.options_.max_message) oversized = true;
    else c.partial.append(data, size);
    if (oversized) c.partial = "\x01";  // swallow the rest of this message
    if (!fin) return 1;
    text.swap(c.partial);
    if (text == "\x01") oversized = true;
  }
  if (oversized) s.reply_error(id, "message larger than " + std::to_string(s.options_.max_message) + " bytes: ignored");
  else if (binary) s.reply_error(id, "binary messages are not commands: send JSON text");
  else s.receive(id, text);
  return 1;
}

void Server::reply_error(ClientId id, const std::string& message) {
  send(id, json{{"type", "error"}, {"message", message}}.dump(), false);
}

// Only JSON objects naming a defined command get through; "rate" (the
// frames a tab wants per second) and "ready" (it took the last one) are the
// server's own.
void Server::receive(ClientId id, const std::string& text) {
  json body = json::parse(text, nullptr, false);
  if (body.is_discarded()) return reply_error(id, "not JSON: ignored");
  if (!body.is_object() || !body.contains("cmd") || !body["cmd"].is_string())
    return reply_error(id, "a command is an object with \"cmd\": NAME");
  const std::string name = body["cmd"];
  if (name == "rate") {
    if (!body.contains("fps") || !body["fps"].is_number() || !(body["fps"].get<double>() >= 0))
      return reply_error(id, "rate: 'fps' must be a number >= 0");
    std::lock_guard<std::mutex> lock(mutex_);
    if (auto it = clients_.find(id); it != clients_.end()) it->second->rate = std::min(options_.max_rate, body["fps"].get<double>());
    update_wants();
    ++news_;
    wake_.notify_all();
    return;
  }
  if (name == "ready") {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (auto it = clients_.find(id); it != clients_.end()) it->second->ready = true;
      update_wants();
      ++news_;
    }
    wake_.notify_all();
    return;
  }
  if (!is_command_(name)) return reply_error(id, "unknown command '" + name + "'");
  on_command_(id, std::move(body));
}

void Server::update_wants() {
  auto due = std::chrono::steady_clock::time_point::max();
  for (const auto& [id, c] : clients_)
    if (c->rate > 0 && c->ready) due = std::min(due, c->next_frame);
  frame_due_ = due.time_since_epoch().count();
}

bool Server::wants_frame() const {
  return std::chrono::steady_clock::now().time_since_epoch().count() >= frame_due_.load(std::memory_order_relaxed);
}

void Server::frame(std::shared_ptr<const std::string> bytes, bool urgent, std::shared_ptr<const std::string> topology) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (topology) {
      topology_ = std::move(topology);
      ++topology_seq_;
    }
    frame_ = std::move(bytes);
    frame_urgent_ = urgent;
    ++frame_seq_;
    ++news_;
  }
  wake_.notify_all();
}

void Server::send(ClientId to, const std::string& bytes, bool binary) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = clients_.find(to);
    if (it == clients_.end()) return;
    it->second->queue.push_back({std::make_shared<const std::string>(bytes), binary});
    ++news_;
  }
  wake_.notify_all();
}

void Server::broadcast(const std::string& text) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto msg = std::make_shared<const std::string>(text);
    for (auto& [id, c] : clients_) c->queue.push_back({msg, false});
    ++news_;
  }
  wake_.notify_all();
}

// The one writer: each tab's queued replies in order, then the topology when
// it has an older one, then the latest frame (always of that topology) when
// it took the last and its rate allows, or the topology is new to it. It
// sleeps until there is news, or until a frame it holds back falls due.
void Server::sender() {
  std::unique_lock<std::mutex> lock(mutex_);
  std::uint64_t seen = 0;
  auto due = std::chrono::steady_clock::time_point::max();
  while (true) {
    const auto news = [&] { return stopping_ || news_ != seen; };
    if (due == std::chrono::steady_clock::time_point::max()) wake_.wait(lock, news);
    else wake_.wait_until(lock, due, news);
    if (stopping_) break;
    seen = news_;
    due = std::chrono::steady_clock::time_point::max();
    const auto now = std::chrono::steady_clock::now();
    std::vector<std::pair<std::shared_ptr<Client>, std::vector<Message>>> work;
    for (auto& [id, c] : clients_) {
      std::vector<Message> out(c->queue.begin(), c->queue.end());
      c->queue.clear();
      const bool new_topology = topology_ && c->topology_sent != topology_seq_;
      if (new_topology) {
        out.push_back({topology_, true});
        c->topology_sent = topology_seq_;
      }
      if (frame_ && c->rate > 0 && c->ready && c->frame_sent != frame_seq_) {
        if (now >= c->next_frame || frame_urgent_ || new_topology) {  // a topology is drawn with its frame
          out.push_back({frame_, true});
          c->frame_sent = frame_seq_;
          c->ready = false;
          c->next_frame = now + std::chrono::microseconds(std::int64_t(1e6 / c->rate));
        } else {
          due = std::min(due, c->next_frame);
        }
      }
      if (!out.empty()) work.push_back({c, std::move(out)});
    }
    update_wants();
    lock.unlock();
    for (auto& [c, messages] : work) {
      std::lock_guard<std::mutex> writing(c->writing);
      for (const Message& m : messages) {
        if (c->closed) break;
        const int op = m.binary ? MG_WEBSOCKET_OPCODE_BINARY : MG_WEBSOCKET_OPCODE_TEXT;
        if (mg_websocket_write(c->conn, op, m.bytes->data(), m.bytes->size()) <= 0) break;
      }
    }
    lock.lock();
  }
}

}  // namespace tendril::studio
