// The calculator page: each section's form drives its endpoint(s); see index.html. The sections'
// inputs live in the URL (url_state.js), so the page starts from it and calculates at once.

import * as bore from './bore.js';
import * as entry from './entry.js';
import * as groove from './groove.js';
import { wirePageHistory } from './page_history.js';
import * as polygon from './polygon.js';
import { wirePrintSheets } from './print_sheet.js';
import { wireSectionTools } from './section_tools.js';
import * as speeds from './speeds.js';

const calculators = [entry, speeds, groove, bore, polygon].map((section) => section.init());
wireSectionTools(calculators);
wirePageHistory(calculators);
wirePrintSheets(calculators);
