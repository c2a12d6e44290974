// The calculator page: each section's form drives its endpoint(s); see index.html. The sections'
// inputs live in the URL (url_state.js), so the page starts from it and calculates at once. The
// static page takes the URL's language and units first, so that every form reads in them. The
// machine profile (machine.js) is edited in the Program time section and times the programs of
// the other sections too: when it changes, they calculate again.

import * as bore from './sections/bore_roughness.js';
import * as entry from './sections/entry_and_main_time.js';
import * as flat from './sections/lathe_flat.js';
import * as groove from './sections/groove_roughness.js';
import * as grooving from './sections/grooving_cycle.js';
import { translatePage } from './core/i18n.js';
import { wirePageHistory } from './core/page_history.js';
import { wirePageSettings } from './core/page_settings.js';
import * as polygon from './sections/polygon_hole.js';
import * as programTime from './sections/program_time.js';
import { wirePrintSheets } from './core/print_sheet.js';
import { wireSectionTools } from './core/section_tools.js';
import * as speeds from './sections/resultant_speeds.js';
import { applyUnitsToPage } from './core/units.js';

translatePage();
applyUnitsToPage();
const calculators = [entry, speeds, groove, bore, polygon, grooving, flat, programTime].map((section) =>
  section.init(),
);
wireMachineProfile(calculators);
wireSectionTools(calculators);
wirePageHistory(calculators);
wirePrintSheets(calculators);
wirePageSettings(calculators);

// An edit of the profile (a calculation of Program time the user asked for) is one of every section
// timed on it: each calculates again if what it uses of the profile changed (url_state.js
// signature), as after an edit of its own inputs. Loading and back/forward calculate every section
// anyway (page_history.js).
function wireMachineProfile(calculators) {
  const profile = calculators.find((c) => c.id === 'program-time');
  const timed = calculators.filter((c) => c !== profile && c.form.dataset.machine !== undefined);
  profile.form.addEventListener('calculation-start', (event) => {
    if (event.detail.cause !== 'input' && event.detail.cause !== 'submit') return;
    for (const calculator of timed) calculator.calculate('input');
  });
}
