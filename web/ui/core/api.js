// Talking to the cutcalc API: JSON bodies with the numbers exactly as typed, problem+json answers
// in the page's language (Accept-Language).

import { language } from './i18n.js';

// A number as the user typed it, written into the JSON text verbatim (normalised to JSON's
// grammar), so that the service, not the browser, judges it: 1e400 is the service's "too large",
// not a silent Infinity or null.
export class RawNumber {
  constructor(text) {
    this.text = text;
  }
}

// JSON text of `value`; RawNumber values are written as they are.
export function toJson(value) {
  if (value instanceof RawNumber) return value.text;
  if (Array.isArray(value)) return `[${value.map(toJson).join(',')}]`;
  if (value !== null && typeof value === 'object') {
    const members = Object.entries(value).map(([k, v]) => `${JSON.stringify(k)}:${toJson(v)}`);
    return `{${members.join(',')}}`;
  }
  return JSON.stringify(value);
}

// The user's text as a JSON number literal, or null when it is not a number. A decimal comma
// is accepted ("1,5" is 1.5), as on the shop floor.
export function numberLiteral(text) {
  let t = text.trim();
  if (/^[+-]?\d*,\d+([eE][+-]?\d+)?$/.test(t)) t = t.replace(',', '.');
  const m = /^([+-]?)(\d*)(?:\.(\d*))?(?:[eE]([+-]?\d+))?$/.exec(t);
  if (!m || (m[2] === '' && (m[3] ?? '') === '')) return null;
  const sign = m[1] === '-' ? '-' : '';
  const int = m[2].replace(/^0+(?=\d)/, '') || '0';
  const frac = m[3] ? `.${m[3]}` : '';
  const exp = m[4] !== undefined ? `e${m[4]}` : '';
  return sign + int + frac + exp;
}

// A client for the API. `onSend` sees every request as it goes out ({path, accept, language,
// body}, the body as the exact JSON text sent), so that a calculation can be repeated outside the
// page ("Copy as curl").
export function apiClient(onSend = () => {}) {
  // POSTs `body` as JSON. Returns {ok, status, json, text, headers}; a problem body is in `json`.
  async function postJson(path, body, accept = 'application/json') {
    const text = toJson(body);
    onSend({ path, accept, language, body: text });
    let response;
    try {
      response = await fetch(path, {
        method: 'POST',
        headers: {
          'Content-Type': 'application/json',
          Accept: accept,
          'Accept-Language': language,
        },
        body: text,
      });
    } catch (error) {
      return { ok: false, status: 0, json: null, text: '', headers: null, networkError: error };
    }
    const answer = await response.text();
    let json = null;
    const type = response.headers.get('Content-Type') ?? '';
    if (/^application\/([a-z0-9.+-]*\+)?json/i.test(type)) {
      try {
        json = JSON.parse(answer);
      } catch {
        json = null;
      }
    }
    const { ok, status, headers } = response;
    return { ok, status, json, text: answer, headers };
  }

  return { postJson };
}

// The client of requests nobody needs to repeat (downloads).
export const { postJson } = apiClient();

// The file name of a Content-Disposition header (attachment; filename="x.ngc"), or `fallback`.
export function fileNameOf(disposition, fallback) {
  const m = /filename="([^"]+)"/.exec(disposition ?? '');
  return m ? m[1] : fallback;
}
