// Results out of the page: a calculation's requests as curl commands, a table as CSV, a file
// saved from the browser. (No import of the page's form modules: form.js saves programs with
// this.)

import { t } from './i18n.js';

// `text` as one shell word: single quotes, a quote inside as '\'' (POSIX sh).
const shellWord = (text) => `'${text.replaceAll("'", "'\\''")}'`;

// The request as a curl command that sends exactly the same bytes to the same URL; -w prints a
// newline after the answer so that several answers come out one per line.
export function curlCommand({ path, accept, language, body }) {
  const url = new URL(path, window.location.href).href;
  return [
    'curl -sS',
    shellWord(url),
    `-H ${shellWord('Content-Type: application/json')}`,
    `-H ${shellWord(`Accept: ${accept}`)}`,
    `-H ${shellWord(`Accept-Language: ${language}`)}`,
    `--data-raw ${shellWord(body)}`,
    `-w ${shellWord('\\n')}`,
  ].join(' ');
}

// Every request of a calculation, one command per line, in the order the page sent them.
export function curlScript(requests) {
  return requests.map(curlCommand).join('\n');
}

// One CSV field (RFC 4180): quoted when it holds a comma, a quote or a line break, a quote
// doubled. Numbers as JavaScript writes them: '.' decimals, the shortest text that reads back
// as the same double.
function csvField(value) {
  const text = value === undefined || value === null ? '' : String(value);
  return /[",\r\n]/.test(text) ? `"${text.replaceAll('"', '""')}"` : text;
}

// RFC 4180 text: CRLF after every record, the first record the header.
export function csvText(header, rows) {
  return [header, ...rows].map((row) => `${row.map(csvField).join(',')}\r\n`).join('');
}

// A header cell: the API's field name, its unit in brackets when it has one (width_mm [mm]).
export const csvHeading = (name, unit) => (unit ? `${name} [${unit}]` : name);

// Saves `text` as a file called `name` (the browser's download).
export function saveFile(name, text, type) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  link.hidden = true;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

// A "Download CSV" button for a table of results. columns = [[field name, unit], ...] (unit ''
// when none), rows = arrays of values in that order.
export function csvButton(id, fileName, columns, rows) {
  const button = document.createElement('button');
  button.type = 'button';
  button.id = id;
  button.className = 'csv-download';
  button.textContent = t('button.download_csv');
  button.addEventListener('click', () => {
    const header = columns.map(([name, unit]) => csvHeading(name, unit));
    saveFile(fileName, csvText(header, rows), 'text/csv;charset=utf-8;header=present');
  });
  return button;
}
