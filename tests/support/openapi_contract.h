#pragma once
// Test support: checks values against openapi.yaml, synchronously, for tests that assert what the
// contract accepts or rejects. The checking is done by the repository's one JSON Schema validator,
// tools/contract/check.mjs (Ajv, JSON Schema 2020-12, strict), run as a child process (Node.js)
// for the life of the OpenApiContract; contract.mjs says what an answer is matched against
// (path templates, the x-cutcalc-unmatched-route 404 and the 405 fallbacks, media types, headers).
// The answers of every test's HTTP exchanges are checked by the same code after the tests
// (support/exchange_log.h), so tests need not call check_response on them.
//
// document() is the YAML read here with yaml-cpp (scalars typed by the YAML 1.2 core schema, as
// JSON numbers keep their integer/float kind), for tests of the document's shape.
//
// Every violation is one string; those about a value start with its JSON Pointer, e.g.
//   at "/start/x_mm": must be number (...)
// An empty vector means the value conforms.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cutcalc::test_support {

class OpenApiContract {
 public:
  enum class Compile { every_schema, when_used };

  // Reads and parses the YAML document and starts the checker, which compiles every schema in it
  // (when_used: each schema when a check first needs it, in half the start-up time); throws
  // std::runtime_error on I/O or parse errors, and, for a schema compiled, on a keyword Ajv does
  // not know and on a $ref that does not resolve.
  static OpenApiContract load(const std::string& path, Compile compile = Compile::every_schema);

  // Violations of an answer (method, path, status, Content-Type, body; a text body as a JSON
  // string, no body as null), matched as tools/contract/contract.mjs says.
  std::vector<std::string> check_response(const std::string& method, const std::string& path,
                                          int status, const std::string& content_type,
                                          const nlohmann::json& body) const;

  // Violations of the operation's application/json request body schema.
  std::vector<std::string> check_request(const std::string& method, const std::string& path,
                                         const nlohmann::json& body) const;

  // Violations of the documented response headers (required ones present, present ones valid).
  std::vector<std::string> check_response_headers(
      const std::string& method, const std::string& path, int status,
      const std::map<std::string, std::string>& headers) const;

  // Violations of an arbitrary value against the schema at a local reference such as
  // "#/components/schemas/Problem".
  std::vector<std::string> check_schema(const std::string& schema_ref,
                                        const nlohmann::json& value) const;

  // The whole document as JSON (YAML scalars typed by the YAML 1.2 core schema).
  nlohmann::json document() const;

 private:
  class Checker;
  OpenApiContract(nlohmann::json document, std::shared_ptr<Checker> checker);

  nlohmann::json document_;
  std::shared_ptr<Checker> checker_;
};

}  // namespace cutcalc::test_support
