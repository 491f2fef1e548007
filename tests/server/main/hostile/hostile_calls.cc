#include "tests/server/main/hostile/hostile_calls.h"

#include <google/protobuf/util/json_util.h>
#include <grpcpp/grpcpp.h>

#include <cctype>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "client/locator_client.h"
#include "server/http/api_error.h"
#include "tests/server/http/json_value.h"

namespace locator::test {
namespace {

using Code = grpc::StatusCode;

void SetDeadline(grpc::ClientContext* context) {
  SetDeadlineFromNow(context, HostileServer::CallDeadline());
}

// A dataset method over HTTP: POST /v1/datasets/{name}:{method}, the name
// taken out of the body.
template <typename Request>
Outcome HttpMethod(HostileServer& server, std::string_view method,
                   Request request, google::protobuf::Message* response) {
  const std::string name =
      request.dataset().empty() ? server.plain().name() : request.dataset();
  request.clear_dataset();
  std::string body;
  if (!google::protobuf::util::MessageToJsonString(request, &body).ok()) {
    Outcome outcome;
    outcome.code = Code::INTERNAL;
    outcome.transport_problem = "the test cannot print its request";
    return outcome;
  }
  return CallHttp(
      server.http_port(), "POST",
      "/v1/datasets/" + PercentEncode(name) + ":" + std::string(method), body,
      {{"Content-Type", "application/json"}}, response);
}

}  // namespace

std::string PercentEncode(std::string_view text) {
  std::string encoded;
  for (unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      encoded += static_cast<char>(c);
    } else {
      char escape[4];
      std::snprintf(escape, sizeof escape, "%%%02X", c);
      encoded += escape;
    }
  }
  return encoded;
}

Outcome CallHttp(int port, std::string_view method, std::string_view target,
                 std::string_view body, const HttpHeaders& headers,
                 google::protobuf::Message* response, HttpReply* reply_out) {
  HttpReply own_reply;
  HttpReply& reply = reply_out != nullptr ? *reply_out : own_reply;
  const Status sent = SendHttp(port, method, target, &reply, body, headers);
  Outcome outcome;
  if (!sent.ok()) {
    outcome.code = Code::UNAVAILABLE;
    outcome.transport_problem = "the HTTP exchange failed: " + sent.ToString();
    return outcome;
  }
  outcome.http_status = reply.status;
  if (reply.status == 200) {
    if (response != nullptr &&
        !google::protobuf::util::JsonStringToMessage(reply.body, response)
             .ok()) {
      outcome.transport_problem = "HTTP 200 whose body is not a " +
                                  response->GetTypeName() + ": " +
                                  Shorten(reply.body);
    }
    return outcome;
  }
  JsonValue error;
  const auto content_type = reply.headers.find("content-type");
  const bool json = content_type != reply.headers.end() &&
                    content_type->second == "application/json" &&
                    ParseJson(reply.body, &error).ok();
  try {
    if (!json) throw std::out_of_range("not JSON");
    outcome.code = static_cast<Code>(error["code"].number());
    outcome.message = error["message"].string();
    if (error["status"].string() != CodeName(outcome.code)) {
      throw std::out_of_range("status is not the code's name");
    }
  } catch (const std::exception& e) {
    outcome.code = Code::UNKNOWN;
    outcome.transport_problem = "HTTP " + std::to_string(reply.status) +
                                " whose body is not an ApiError (" + e.what() +
                                "): " + Shorten(reply.body);
    return outcome;
  }
  // Where HTTP has a more precise status than the code's (ApiError).
  const bool http_refusal = reply.status == 405 || reply.status == 406 ||
                            reply.status == 413 || reply.status == 414 ||
                            reply.status == 415 || reply.status == 431;
  if (reply.status !=
          HttpStatusForCanonicalCode(static_cast<int>(outcome.code)) &&
      !http_refusal) {
    outcome.transport_problem = "HTTP " + std::to_string(reply.status) +
                                " for " + CodeName(outcome.code) + " \"" +
                                Shorten(outcome.message) + "\"";
  }
  return outcome;
}

Outcome CallLocate(HostileServer& server, Transport transport,
                   const v1::LocateRequest& request,
                   v1::LocateResponse* response) {
  if (transport == Transport::kHttp) {
    return HttpMethod(server, "locate", request, response);
  }
  grpc::ClientContext context;
  SetDeadline(&context);
  return FromGrpc(server.stub().Locate(&context, request, response));
}

Outcome CallLocateBatch(HostileServer& server, Transport transport,
                        const v1::LocateBatchRequest& request,
                        v1::LocateBatchResponse* response) {
  if (transport == Transport::kHttp) {
    return HttpMethod(server, "locateBatch", request, response);
  }
  grpc::ClientContext context;
  SetDeadline(&context);
  return FromGrpc(server.stub().LocateBatch(&context, request, response));
}

Outcome CallProfile(HostileServer& server, Transport transport,
                    const v1::ProfileRequest& request,
                    v1::ProfileResponse* response) {
  if (transport == Transport::kHttp) {
    return HttpMethod(server, "profile", request, response);
  }
  grpc::ClientContext context;
  SetDeadline(&context);
  return FromGrpc(server.stub().Profile(&context, request, response));
}

Outcome CallGrid(HostileServer& server, Transport transport,
                 const v1::GridRequest& request, v1::GridResponse* whole) {
  if (transport == Transport::kHttp) {
    return HttpMethod(server, "grid", request, whole);
  }
  grpc::ClientContext context;
  SetDeadline(&context);
  auto reader = server.stub().Grid(&context, request);
  v1::GridResponse message;
  std::vector<std::vector<double>> rows;
  std::string problem;
  for (int count = 0; reader->Read(&message); ++count) {
    if (message.has_header() != (count == 0) && problem.empty()) {
      problem = "a Grid stream's header in message " + std::to_string(count);
    }
    if (message.has_header()) {
      *whole->mutable_header() = message.header();
      rows.assign(message.header().height(), {});
    }
    const int64_t width = whole->header().width();
    for (uint32_t r = 0; r < message.rows() && problem.empty(); ++r) {
      const uint64_t row = uint64_t{message.first_row()} + r;
      if (row >= rows.size() || !rows[row].empty() ||
          message.values_size() != int64_t{message.rows()} * width) {
        problem = "a Grid stream's row " + std::to_string(row) + " is out " +
                  "of place, repeated or of the wrong size";
        break;
      }
      rows[row].assign(message.values().begin() + r * width,
                       message.values().begin() + (r + 1) * width);
    }
  }
  Outcome outcome = FromGrpc(reader->Finish());
  if (outcome.code != Code::OK) return outcome;
  for (const std::vector<double>& row : rows) {
    if (row.empty() && whole->header().width() > 0 && problem.empty()) {
      problem = "a Grid stream left a row out";
    }
    whole->mutable_values()->Add(row.begin(), row.end());
  }
  whole->set_rows(static_cast<uint32_t>(rows.size()));
  outcome.transport_problem = problem;
  return outcome;
}

Outcome CallStream(HostileServer& server,
                   const std::vector<v1::LocateRequest>& requests,
                   std::vector<v1::LocateResponse>* answers) {
  grpc::ClientContext context;
  SetDeadline(&context);
  auto stream = server.stub().LocateStream(&context);
  std::thread writer([&] {
    for (const v1::LocateRequest& request : requests) {
      if (!stream->Write(request)) return;
    }
    stream->WritesDone();
  });
  v1::LocateResponse response;
  while (stream->Read(&response)) answers->push_back(response);
  writer.join();
  return FromGrpc(stream->Finish());
}

}  // namespace locator::test
