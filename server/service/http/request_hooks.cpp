#include "service/http/request_hooks.hpp"

#include <chrono>
#include <cmath>
#include <string>

#include "service/http/guarded_server.hpp"
#include "service/http/problem.hpp"
#include "service/http/request_id.hpp"
#include "service/ops/log.hpp"
#include "service/runs/metrics.hpp"

namespace saasgaps::service {

void install_request_hooks(httplib::Server& server, const RequestGuard& guard) {
  server.set_exception_handler(respond_to_exception);
  server.set_error_handler(httplib::Server::HandlerWithResponse([](const httplib::Request& req, httplib::Response& res) {
    // A path that exists, asked with a method it does not have: 405 naming the ones it has.
    const std::string allow = allowed_methods(req.path);
    if (res.status == 404 && res.body.empty() && !allow.empty()) {
      res.set_header("Allow", allow);
      write_problem(res, 405, "Method Not Allowed", req.method + " " + req.path + ": allowed methods are " + allow);
    }
    fill_error_body(req, res);
    return httplib::Server::HandlerResponse::Handled;
  }));
  server.set_pre_routing_handler([&guard](const httplib::Request& req, httplib::Response& res) {
    res.set_header("X-Request-Id", request_id(req));
    if (!guard.admit(req, res)) return httplib::Server::HandlerResponse::Handled;
    // No route here takes PUT, PATCH and the like: answer before cpp-httplib waits for their body.
    // (GET, POST and DELETE on a path without them reach the error handler above as a 404.)
    const bool served_method = req.method == "GET" || req.method == "HEAD" || req.method == "POST" ||
                               req.method == "DELETE" || req.method == "OPTIONS";
    const std::string allow = allowed_methods(req.path);
    if (!served_method && !allow.empty()) {
      res.set_header("Allow", allow);
      res.set_header("Connection", "close");
      GuardedServer::close_after_response();
      write_problem(res, 405, "Method Not Allowed", req.method + " " + req.path + ": allowed methods are " + allow);
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  server.set_logger([](const httplib::Request& req, const httplib::Response& res) {
    std::string id = res.get_header_value("X-Request-Id");
    if (id.empty()) id = request_id(req);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                                 GuardedServer::request_started())
                          .count();
    const std::string route = route_label(req.path);
    Metrics::global().count_request(route, res.status);
    log_info("http_request", {{"request_id", id},
                              {"method", req.method},
                              {"path", req.path},
                              {"route", route},
                              {"status", res.status},
                              {"ms", std::round(ms * 1000.0) / 1000.0},
                              {"bytes", res.body.size()},
                              {"remote", req.remote_addr}});
  });
}

}  // namespace saasgaps::service
