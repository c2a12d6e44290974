// The calculator page: each section's form drives its endpoint(s); see index.html. The sections'
// inputs live in the URL (url_state.js), so the page starts from it and calculates at once. The
// static page takes the URL's language and units first, so that every form reads in them.

import * as bore from './bore.js';
import * as entry from './entry.js';
import * as flat from './flat.js';
import * as groove from './groove.js';
import * as grooving from './grooving.js';
import { translatePage } from './i18n.js';
import { wirePageHistory } from './page_history.js';
import { wirePageSettings } from './page_settings.js';
import * as polygon from './polygon.js';
import { wirePrintSheets } from './print_sheet.js';
import { wireSectionTools } from './section_tools.js';
import * as speeds from './speeds.js';
import { applyUnitsToPage } from './units.js';

translatePage();
applyUnitsToPage();
const calculators = [entry, speeds, groove, bore, polygon, grooving, flat].map((section) => section.init());
wireSectionTools(calculators);
wirePageHistory(calculators);
wirePrintSheets(calculators);
wirePageSettings(calculators);
