// openapi.yaml as a contract checker: the one JSON Schema validator of the repository (Ajv, JSON
// Schema draft 2020-12, the dialect of OpenAPI 3.1, in strict mode: a keyword Ajv does not know
// or a $ref that does not resolve fails the load, so no schema passes because it was not
// understood). Used by check.mjs (the C++ tests' exchanges and synchronous checks) and replay.mjs.
//
// What an answer is checked against, given (method, path, status, Content-Type):
//   - the operation `paths[template][method]`, the path matched literally or by its template
//     (`/ui/{asset}`); HEAD without its own operation is checked against GET, without a body;
//   - an undocumented path answered 404: the document's `x-cutcalc-unmatched-route` response;
//   - a documented path answered 405 for a method it does not list: the path's documented 405;
//   - the response `responses[status]`, else `NXX`, else `default`;
//   - its headers: every `required` header present, every documented header present matches its
//     schema (names case-insensitive);
//   - its media type: the documented key whose essence matches (`*/*`, `type/*` allowed) and whose
//     parameters are exactly the actual ones (values case-insensitive; none missing or extra, as
//     generated clients match); a response documented without content must have no body;
//   - its body against the media type's schema (JSON bodies parsed, other bodies as a string).
// Every violation is one string; those about a value start with `at "<JSON Pointer>": `.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';

const require = createRequire(import.meta.url);
const Ajv2020 = require('ajv/dist/2020').default;
const addFormats = require('ajv-formats').default;
const YAML = require('yaml');

const METHODS = ['get', 'put', 'post', 'delete', 'options', 'head', 'patch', 'trace'];
// OpenAPI 3.1's own schema keywords (annotations for validation).
const OPENAPI_KEYWORDS = ['discriminator', 'xml', 'externalDocs', 'example'];
const DOC_ID = 'urn:cutcalc:openapi';

const escapeToken = t => String(t).replace(/~/g, '~0').replace(/\//g, '~1');
const pointer = parts => parts.map(p => '/' + escapeToken(p)).join('');

export function isJsonMediaType(type) {
  return /^application\/([a-z0-9.+-]*\+)?json\b/i.test(type ?? '');
}

function parseMediaType(text) {
  const [essence, ...params] = String(text).split(';');
  const out = { essence: essence.trim().toLowerCase(), params: {} };
  for (const p of params) {
    const eq = p.indexOf('=');
    if (eq < 0) continue;
    out.params[p.slice(0, eq).trim().toLowerCase()] = p.slice(eq + 1).trim().replace(/^"(.*)"$/, '$1').toLowerCase();
  }
  return out;
}

function essenceMatches(documented, actual) {
  if (documented === '*/*' || documented === actual) return true;
  return documented.endsWith('/*') && actual.startsWith(documented.slice(0, -1));
}

// Every key starting with x- anywhere in the document (extensions are annotations to Ajv).
function extensionKeys(node, out = new Set()) {
  if (Array.isArray(node)) node.forEach(n => extensionKeys(n, out));
  else if (node && typeof node === 'object') {
    for (const [k, v] of Object.entries(node)) {
      if (k.startsWith('x-')) out.add(k);
      extensionKeys(v, out);
    }
  }
  return out;
}

export function formatAjvError(e) {
  const at = e.instancePath;
  switch (e.keyword) {
    case 'required':
      return `at "${at}": missing required property "${e.params.missingProperty}" (expected at "${at}/${escapeToken(e.params.missingProperty)}")`;
    case 'additionalProperties':
      return `at "${at}/${escapeToken(e.params.additionalProperty)}": property "${e.params.additionalProperty}" is not allowed (additionalProperties: false)`;
    case 'dependentRequired':
      return `at "${at}": property "${e.params.property}" requires property "${e.params.missingProperty}" (dependentRequired; expected at "${at}/${escapeToken(e.params.missingProperty)}")`;
    default:
      return `at "${at}": ${e.message} (${e.keyword} ${JSON.stringify(e.params)}; schema ${e.schemaPath})`;
  }
}

export class Contract {
  // Reads the YAML document and compiles every schema in it (with compileAll false: each schema
  // when first used); throws Error on I/O and parse errors, a keyword Ajv does not know and a $ref
  // that does not resolve.
  constructor(file, { compileAll = true } = {}) {
    const text = readFileSync(file, 'utf8');
    const parsed = YAML.parseDocument(text, { schema: 'core', prettyErrors: true });
    if (parsed.errors.length) throw new Error(`openapi: cannot load ${file}: ${parsed.errors.map(e => e.message).join('; ')}`);
    this.document = parsed.toJSON();
    if (!this.document || typeof this.document !== 'object' || !this.document.openapi || !this.document.paths) {
      throw new Error(`openapi: ${file} is not an OpenAPI document`);
    }
    this.ajv = new Ajv2020({ inlineRefs: false, strict: true, strictTypes: false, strictRequired: false, allErrors: true, validateFormats: true });
    addFormats(this.ajv);
    // The document is one schema resource whose OpenAPI fields are annotations: `#/components/...`
    // resolves inside it; only the schemas below are compiled.
    const annotations = new Set([...OPENAPI_KEYWORDS, ...extensionKeys(this.document), ...Object.keys(this.document)]);
    for (const k of annotations) if (!this.ajv.getKeyword(k)) this.ajv.addKeyword({ keyword: k });
    const { $schema, $id, ...rest } = this.document;
    this.ajv.addSchema({ ...rest, $id: DOC_ID }, DOC_ID, undefined, false);
    this.validators = new Map();
    const problems = [];
    for (const where of compileAll ? this.schemaLocations() : []) {
      try {
        this.validator(where);
      } catch (e) {
        problems.push(`${where}: ${e.message}`);
      }
    }
    if (problems.length) {
      throw new Error(`openapi: ${file} uses what the contract checker does not support:\n  ${problems.join('\n  ')}`);
    }
  }

  // JSON Pointers of every schema: components.schemas, request bodies, responses, headers.
  *schemaLocations() {
    const d = this.document;
    for (const name of Object.keys(d.components?.schemas ?? {})) yield pointer(['components', 'schemas', name]);
    for (const name of Object.keys(d.components?.headers ?? {})) {
      if (d.components.headers[name]?.schema) yield pointer(['components', 'headers', name, 'schema']);
    }
    const inResponse = function* (parts, response) {
      for (const [type, media] of Object.entries(response?.content ?? {})) {
        if (media?.schema) yield pointer([...parts, 'content', type, 'schema']);
      }
      for (const [name, h] of Object.entries(response?.headers ?? {})) {
        if (h?.schema) yield pointer([...parts, 'headers', name, 'schema']);
      }
    };
    for (const [name, r] of Object.entries(d.components?.responses ?? {})) yield* inResponse(['components', 'responses', name], r);
    for (const [p, item] of Object.entries(d.paths)) {
      for (const m of METHODS) {
        const op = item?.[m];
        if (!op) continue;
        for (const [type, media] of Object.entries(op.requestBody?.content ?? {})) {
          if (media?.schema) yield pointer(['paths', p, m, 'requestBody', 'content', type, 'schema']);
        }
        for (const [status, r] of Object.entries(op.responses ?? {})) yield* inResponse(['paths', p, m, 'responses', status], r);
      }
    }
    const unmatched = d['x-cutcalc-unmatched-route']?.response;
    if (unmatched) yield* inResponse(['x-cutcalc-unmatched-route', 'response'], unmatched);
  }

  validator(where) {
    let v = this.validators.get(where);
    if (!v) {
      v = this.ajv.compile({ $ref: `${DOC_ID}#${encodeURI(where).replace(/#/g, '%23')}` });
      this.validators.set(where, v);
    }
    return v;
  }

  // The object at a JSON Pointer, following $ref; with its pointer.
  at(ptr) {
    let cur = this.document;
    let where = ptr;
    for (const part of ptr.split('/').slice(1)) {
      cur = cur?.[part.replace(/~1/g, '/').replace(/~0/g, '~')];
    }
    while (cur && typeof cur === 'object' && typeof cur.$ref === 'string' && cur.$ref.startsWith('#/')) {
      where = cur.$ref.slice(1);
      cur = this.at(where).value;
    }
    return { value: cur, where };
  }

  validate(where, value) {
    const v = this.validator(where);
    return v(value) ? [] : v.errors.map(formatAjvError);
  }

  // The documented path template for a request path (query string ignored), or undefined.
  template(requestPath) {
    const p = requestPath.split('?')[0];
    if (this.document.paths[p]) return p;
    const segments = p.split('/');
    return Object.keys(this.document.paths).find(t => {
      const ts = t.split('/');
      return ts.length === segments.length && ts.every((s, i) => (/^\{[^}]+\}$/.test(s) ? segments[i] !== '' : s === segments[i]));
    });
  }

  // { where, response } for the answer, or { violation }.
  findResponse(method, requestPath, status) {
    const m = method.toLowerCase();
    const what = `${method.toUpperCase()} ${requestPath}`;
    const t = this.template(requestPath);
    if (t === undefined) {
      if (status === 404 && this.document['x-cutcalc-unmatched-route']) {
        return { where: '/x-cutcalc-unmatched-route/response', ...this.resolved('/x-cutcalc-unmatched-route/response') };
      }
      return { violation: `${what}: path is not documented (and status ${status} is not 404)` };
    }
    const item = this.document.paths[t];
    const base = pointer(['paths', t]);
    let op = m;
    if (!item[m] && m === 'head' && item.get) op = 'get';
    if (!item[op]) {
      if (status === 405) {
        const other = METHODS.find(k => item[k]?.responses?.['405']);
        if (other) return this.resolved(`${base}/${other}/responses/405`);
      }
      return { violation: `${what}: operation is not documented` };
    }
    const responses = item[op].responses ?? {};
    for (const key of [String(status), `${Math.floor(status / 100)}XX`, 'default']) {
      if (responses[key]) return this.resolved(pointer(['paths', t, op, 'responses', key]));
    }
    return { violation: `${what}: status ${status} is not documented (documented: ${Object.keys(responses).join(', ')})` };
  }

  resolved(ptr) {
    const { value, where } = this.at(ptr);
    return { response: value, where };
  }

  // Violations of a whole answer. headers: object (names any case) or undefined to skip them;
  // body: the parsed value (JSON) or string, undefined or null when there is none (the body of a
  // HEAD answer, absent, is not validated; its Content-Type is).
  checkResponse({ method, path, status, contentType, headers, body }) {
    const head = method.toUpperCase() === 'HEAD';
    const found = this.findResponse(method, path, status);
    if (found.violation) return [found.violation];
    const out = headers ? this.headerViolations(found, headers) : [];
    const what = `${method.toUpperCase()} ${path} ${status}`;
    const content = found.response?.content ?? {};
    if (Object.keys(content).length === 0) {
      if (body !== undefined && body !== null && body !== '') out.push(`${what}: the response is documented without a body`);
      return out;
    }
    if (!contentType || !contentType.trim()) {
      out.push(`${what}: no Content-Type (documented: ${Object.keys(content).join(', ')})`);
      return out;
    }
    const actual = parseMediaType(contentType);
    let best;
    let bestScore = -1;
    for (const key of Object.keys(content)) {
      const doc = parseMediaType(key);
      if (!essenceMatches(doc.essence, actual.essence)) continue;
      const names = Object.keys(doc.params);
      if (names.length !== Object.keys(actual.params).length || !names.every(k => actual.params[k] === doc.params[k])) continue;
      const score = (doc.essence === actual.essence ? 1000 : doc.essence === '*/*' ? 0 : 500) + Object.keys(doc.params).length;
      if (score > bestScore) [best, bestScore] = [key, score];
    }
    if (best === undefined) {
      out.push(`${what}: Content-Type "${contentType}" is not documented (documented: ${Object.keys(content).join(', ')})`);
      return out;
    }
    if (head || !content[best].schema) return out;
    return out.concat(this.validate(`${found.where}${pointer(['content', best, 'schema'])}`, body ?? null));
  }

  headerViolations(found, headers) {
    const out = [];
    const byName = new Map(Object.entries(headers).map(([k, v]) => [k.toLowerCase(), v]));
    for (const [name, ref] of Object.entries(found.response?.headers ?? {})) {
      const { value: h, where } = this.at(`${found.where}${pointer(['headers', name])}`);
      if (!byName.has(name.toLowerCase())) {
        if (h?.required) out.push(`header ${name}: required but missing`);
        continue;
      }
      if (h?.schema) {
        for (const v of this.validate(`${where}/schema`, String(byName.get(name.toLowerCase())))) out.push(`header ${name}: ${v}`);
      }
      void ref;
    }
    return out;
  }

  checkResponseHeaders(method, path, status, headers) {
    const found = this.findResponse(method, path, status);
    return found.violation ? [found.violation] : this.headerViolations(found, headers);
  }

  // Violations of the operation's application/json request body schema.
  checkRequest(method, path, body) {
    const m = method.toLowerCase();
    const what = `${method.toUpperCase()} ${path}`;
    const t = this.template(path);
    const op = t === undefined ? undefined : this.document.paths[t][m];
    if (!op) return [`${what}: operation is not documented`];
    if (!op.requestBody) return body === undefined || body === null ? [] : [`${what}: the operation takes no request body`];
    const { value: rb, where } = this.at(pointer(['paths', t, m, 'requestBody']));
    const key = Object.keys(rb?.content ?? {}).find(k => parseMediaType(k).essence === 'application/json');
    if (key === undefined) return [`${what}: no application/json request body is documented`];
    if (!rb.content[key].schema) return [];
    return this.validate(`${where}${pointer(['content', key, 'schema'])}`, body);
  }

  // Violations of a value against the schema at a local reference ("#/components/schemas/Problem").
  checkSchema(ref, value) {
    if (!ref.startsWith('#/')) throw new Error(`not a local reference: ${ref}`);
    return this.validate(ref.slice(1), value);
  }
}
