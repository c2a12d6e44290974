// The calculator page: each section's form drives its endpoint(s); see index.html.

import * as bore from './bore.js';
import * as entry from './entry.js';
import * as groove from './groove.js';
import * as polygon from './polygon.js';
import * as speeds from './speeds.js';

for (const section of [entry, speeds, groove, bore, polygon]) section.init();
