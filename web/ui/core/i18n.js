// The page's language: the `lang` page setting of the URL (url_state.js), English by default.
// Every word the page shows comes from one catalogue per language (catalogue_en.js,
// catalogue_ru.js, the same keys); paper symbols and numbers are not words and stay as they are.
// A catalogue text may hold {name} placeholders and subscripts written _{...} (S_{0}).

import en from './catalogue_en.js';
import ru from './catalogue_ru.js';

const CATALOGUES = { en, ru };

const asked = new URLSearchParams(window.location.search).get('lang');
export const language = Object.hasOwn(CATALOGUES, asked) ? asked : 'en';
export const LANGUAGES = Object.keys(CATALOGUES);

// The text of `key` with its {placeholders} filled, subscript marks kept (for SVG and attributes,
// see plainText for people-facing attributes).
function raw(key, params = {}) {
  const text = CATALOGUES[language][key];
  // A missing key is a bug of the page: say so loudly (the browser tests fail on console errors).
  if (text === undefined) {
    console.error(`i18n: no "${key}" in the ${language} catalogue`);
    return key;
  }
  return text.replace(/\{(\w+)\}/g, (m, name) => (name in params ? String(params[name]) : m));
}

// The text of `key` as a plain string (a subscript written inline: S_{0} -> S0).
export function t(key, params) {
  return raw(key, params).replace(/_\{([^}]*)\}/g, '$1');
}

// The text of `key` as DOM nodes: text, and <sub> for each _{...}.
export function tn(key, params) {
  const parts = raw(key, params).split(/_\{([^}]*)\}/);
  return parts.map((part, i) => (i % 2 ? subscript(part) : part)).filter((p) => p !== '');
}

function subscript(text) {
  const sub = document.createElement('sub');
  sub.textContent = text;
  return sub;
}

// Fills the static page: data-i18n="key" elements get their text, data-i18n-aria-label="key"
// their accessible name; <html lang> says the language.
export function translatePage(root = document) {
  document.documentElement.lang = language;
  for (const element of root.querySelectorAll('[data-i18n]')) {
    element.replaceChildren(...tn(element.dataset.i18n));
  }
  for (const element of root.querySelectorAll('[data-i18n-aria-label]')) {
    element.setAttribute('aria-label', t(element.dataset.i18nAriaLabel));
  }
}
