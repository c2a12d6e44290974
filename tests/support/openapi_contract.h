#pragma once
// Test support: checks real requests and responses against openapi.yaml.
//
// OpenApiContract loads the OpenAPI 3.1 document (YAML, through yaml-cpp) into JSON and validates
// bodies with a JSON Schema subset that covers what openapi.yaml uses: boolean schemas, $ref
// (local,
// "#/..."), type (string or array; "integer" = a number without a fractional part), enum, const,
// properties, required, additionalProperties (false or a schema), dependentRequired,
// dependentSchemas, items, minItems, maxItems, minLength, maxLength, pattern (ECMAScript,
// unanchored, as JSON Schema says), minimum, maximum, exclusiveMinimum, exclusiveMaximum (3.1
// numeric form), allOf, anyOf, oneOf (exactly one), not. Annotations (title, description, default,
// example(s), format, discriminator, ...) are ignored. load() throws if any schema in the document
// uses another keyword, so a schema can never pass a check because the checker did not understand
// it.
//
// Every violation is one string that starts with the JSON Pointer of the offending value, e.g.
//   at "/start/x_mm": expected type number, got string
// An empty vector means the value conforms.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cutcalc::test_support {

class OpenApiContract {
 public:
  // Reads and parses the YAML document; throws std::runtime_error on I/O or parse errors, on an
  // unsupported schema keyword and on a $ref that does not resolve.
  static OpenApiContract load(const std::string& path);

  // Violations of the response schema for (method, path template, status, Content-Type). The
  // method is case-insensitive ("POST", "get"); the path is a template exactly as under `paths`
  // ("/v1/entry-length"). Media type parameters in content_type are compared with the documented
  // key: the same parameters with equal values (charset case-insensitively), none missing or extra.
  // An undocumented path, operation, status or media type is itself a violation, except:
  // an undocumented path with status 404 is checked against the document's
  // `x-cutcalc-unmatched-route` response, and an undocumented method on a documented path with
  // status 405 against the path's documented 405 response.
  // For a response documented without content, any body other than null is a violation; the body
  // of a HEAD response (absent) is not validated, its Content-Type is.
  std::vector<std::string> check_response(const std::string& method, const std::string& path,
                                          int status, const std::string& content_type,
                                          const nlohmann::json& body) const;

  // Violations of the operation's application/json request body schema.
  std::vector<std::string> check_request(const std::string& method, const std::string& path,
                                         const nlohmann::json& body) const;

  // Violations of the documented response headers: every header marked `required` must be present
  // and every documented header that is present must match its schema (as a string). Header names
  // are compared case-insensitively; the same 404/405 fallbacks as check_response apply.
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
  explicit OpenApiContract(nlohmann::json document);

  // The response object (with $ref resolved) for the request, or nullptr with a violation.
  const nlohmann::json* find_response(const std::string& method, const std::string& path,
                                      int status, std::vector<std::string>& violations) const;

  nlohmann::json document_;
};

}  // namespace cutcalc::test_support
