// @hey-api/openapi-ts settings for scripts/ci-codegen.sh. The input document and the output
// directory come from HEYAPI_INPUT and HEYAPI_OUTPUT (the command line's -o would replace the
// whole `output` object below).
import { defineConfig } from '@hey-api/openapi-ts';

const need = name => {
  const value = process.env[name];
  if (!value) throw new Error(`openapi-ts.config.mjs: ${name} is not set`);
  return value;
};

export default defineConfig({
  input: need('HEYAPI_INPUT'),
  output: {
    path: need('HEYAPI_OUTPUT'),
    // Relative imports end in `.js`, as Node's ESM loader and tsc's NodeNext resolution need.
    module: { extension: '.js' },
  },
  plugins: ['@hey-api/typescript', '@hey-api/sdk', '@hey-api/client-fetch'],
  logs: { file: false },
});
