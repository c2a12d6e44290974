// Calls a live cutcalc through the SDK that @hey-api/openapi-ts generated from openapi.yaml
// (scripts/ci-codegen.sh copies this file next to the generated ./heyapi/ and compiles both with
// tsc --strict): GET /healthz and /version with typed reads of their answers, then, for every
// reference file, its first status-200 request through the SDK function of the file's endpoint
// (the operationId of POST <endpoint> in openapi.yaml). Only the SDK's runtime is checked here: the
// request types are checked by the openapi-typescript client (gen-reference-client.mjs).
import { readFileSync, readdirSync } from "node:fs";
import path from "node:path";
import { parse } from "yaml";
import * as sdk from "./heyapi/index.js";
import { client } from "./heyapi/client.gen.js";

const baseUrl = process.env.CUTCALC_URL;
const openapiFile = process.env.OPENAPI_FILE;
const referenceDir = process.env.CUTCALC_REFERENCE_DIR;
if (!baseUrl || !openapiFile || !referenceDir) {
  console.error("heyapi-smoke: CUTCALC_URL, OPENAPI_FILE and CUTCALC_REFERENCE_DIR must be set");
  process.exit(2);
}
client.setConfig({ baseUrl });

const failures: string[] = [];
let calls = 0;

async function main(): Promise<void> {
  const health = await sdk.getHealth();
  calls++;
  // Typed reads: the generated response types must have these fields.
  if (health.response.status !== 200 || health.data?.status === undefined) {
    failures.push(`GET /healthz: ${health.response.status} ${JSON.stringify(health.data ?? health.error)}`);
  }
  const version = await sdk.getVersion();
  calls++;
  if (version.response.status !== 200 || version.data?.version === undefined) {
    failures.push(`GET /version: ${version.response.status} ${JSON.stringify(version.data ?? version.error)}`);
  }

  const document = parse(readFileSync(openapiFile!, "utf8")) as {
    paths: Record<string, { post?: { operationId?: string } }>;
  };
  const operations = sdk as unknown as Record<string, unknown>;
  // reference/*.json plus the next/ files of the route table (CUTCALC_ROUTES_FILE: cutcalc --routes).
  const routesFile = process.env.CUTCALC_ROUTES_FILE;
  const nextFiles = routesFile
    ? (JSON.parse(readFileSync(routesFile, "utf8")) as { next_reference_files: string[] }[]).flatMap(r => r.next_reference_files)
    : [];
  const files = [...new Set([...readdirSync(referenceDir!).filter(f => f.endsWith(".json")), ...nextFiles])].sort();
  for (const file of files) {
    const reference = JSON.parse(readFileSync(path.join(referenceDir!, file), "utf8")) as {
      endpoint: string;
      cases: { id: string; request: unknown; expect: { status: number } }[];
    };
    const first = reference.cases.find(c => c.expect.status === 200);
    const operationId = document.paths[reference.endpoint]?.post?.operationId;
    const call = operationId === undefined ? undefined : operations[operationId];
    if (first === undefined) continue;
    if (typeof call !== "function") {
      failures.push(`${file}: no SDK function for POST ${reference.endpoint} (operationId ${operationId})`);
      continue;
    }
    const answer = (await call({ body: first.request })) as { response: Response; data?: unknown; error?: unknown };
    calls++;
    if (answer.response.status !== 200 || typeof answer.data !== "object" || answer.data === null) {
      failures.push(`${file}:${first.id} via ${operationId}: ${answer.response.status} ${JSON.stringify(answer.error ?? answer.data).slice(0, 300)}`);
    }
  }
}

main().then(
  () => {
    for (const f of failures) console.log(`FAIL ${f}`);
    console.log(`hey-api SDK: ${calls - failures.length}/${calls} calls answered as expected`);
    process.exit(failures.length ? 1 : 0);
  },
  (e: unknown) => {
    console.error(e);
    process.exit(2);
  },
);
