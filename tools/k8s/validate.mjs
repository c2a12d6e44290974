#!/usr/bin/env node
// Validates the rendered cutcalc kustomize base (`kubectl kustomize deploy/k8s`) offline.
//
//   node tools/k8s/validate.mjs [FILE]       (no FILE or "-": standard input)
//       Validates; prints every failure; closing line "k8s: N passed, M failed"; exit 1 on any.
//   node tools/k8s/validate.mjs --expect-reject MESSAGE FILE [--expect-reject MESSAGE FILE]...
//       Proves the checks can fail: each FILE (a deliberately broken rendering) must be rejected
//       with a failure that contains MESSAGE. Closing line "k8s-broken: N passed, M failed".
//
// Three layers, every failure is reported (not only the first):
//  1. schema: each object goes through kubernetes-models' class for its apiVersion/kind
//     (`new Deployment(obj).validate()`: Kubernetes' OpenAPI schema as compiled ajv code: types,
//     required fields, formats). An apiVersion/kind that kubernetes-models does not know fails.
//  2. strict fields: those OpenAPI schemas allow unknown properties, so a misspelled field
//     (`readinesProbe`, `replcas`) would pass (1), and the API server would drop it or reject
//     it only at apply time. Each object is compiled as an object literal typed with
//     kubernetes-models' TypeScript interface for its kind; every property that the type does
//     not have, at any depth, is reported (with the nearest known name), as are type errors.
//  3. project rules for cutcalc (replicas, probes, security context, resources, env, drain
//     timing, spreading, and that the Service, HPA and PDB point at the Deployment's pods).
import { readFileSync } from "node:fs";
import path from "node:path";
import { fileURLToPath } from "node:url";
import { parseAllDocuments } from "yaml";
import ts from "typescript";

const here = path.dirname(fileURLToPath(import.meta.url));
const idOf = (obj) => `${obj.kind ?? "?"}/${obj.metadata?.name ?? "?"}`;
let previousProgram; // TypeScript program of the last input, reused by the next one

// Validates one rendered multi-document YAML text: { passed, failures: [string], ids: [string] }.
export async function validateText(text) {
  let passed = 0;
  const failures = [];
  const check = (ok, what, detail = "") => {
    if (ok) {
      passed += 1;
    } else {
      failures.push(detail ? `${what}: ${detail}` : what);
    }
    return ok;
  };

  // ---------------------------------------------------------------- input
  const objects = [];
  for (const [index, doc] of parseAllDocuments(text).entries()) {
    for (const problem of [...doc.errors, ...doc.warnings]) {
      check(false, `YAML document ${index + 1}`, problem.message.split("\n")[0]);
    }
    if (doc.errors.length) continue;
    const value = doc.toJS();
    if (value === null || value === undefined) continue; // empty document
    if (typeof value !== "object" || Array.isArray(value)) {
      check(false, `YAML document ${index + 1}`, "is not a mapping");
      continue;
    }
    objects.push(value);
  }
  check(objects.length > 0, "input", "no Kubernetes objects in the rendered YAML");

  // ---------------------------------------------------------------- 1. schema (kubernetes-models)
  // kubernetes-models has one module per kind: kubernetes-models/<apiVersion>/<Kind>, the class
  // exported under the kind's name and its interface as I<Kind>.
  const models = []; // { obj, modulePath, kind } for the strict pass
  for (const obj of objects) {
    const id = idOf(obj);
    const { apiVersion, kind } = obj;
    if (
      typeof apiVersion !== "string" ||
      !/^([a-z0-9.-]+\/)?v[0-9]+((alpha|beta)[0-9]+)?$/.test(apiVersion) ||
      typeof kind !== "string" ||
      !/^[A-Z][A-Za-z0-9]*$/.test(kind)
    ) {
      check(
        false,
        `${id} schema`,
        `malformed apiVersion/kind: ${JSON.stringify(apiVersion)} ${JSON.stringify(kind)}`,
      );
      continue;
    }
    const modulePath = `kubernetes-models/${apiVersion}/${kind}`;
    let Model;
    try {
      Model = (await import(modulePath))[kind];
    } catch {
      Model = undefined;
    }
    if (
      !check(
        typeof Model === "function" && Model.apiVersion === apiVersion && Model.kind === kind,
        `${id} schema`,
        `unknown kind ${apiVersion}/${kind} (kubernetes-models has no such model)`,
      )
    ) {
      continue;
    }
    try {
      new Model(obj).validate();
      check(true, `${id} schema`);
    } catch (error) {
      check(false, `${id} schema (${apiVersion})`, error.message);
    }
    models.push({ obj, modulePath, kind });
  }

  // ---------------------------------------------------------------- 2. strict fields (TypeScript)
  // Emits every object as `const oN: I<Kind> = <literal>;`, one property per line, remembering the
  // path of each line, so that a diagnostic can name the object and the field.
  function strictFieldCheck() {
    const lines = [];
    const lineInfo = []; // per line: { id, path }
    const emit = (line, id, at) => {
      lines.push(line);
      lineInfo.push({ id, path: at });
    };
    const literal = (value, id, at, indent, prefix, suffix) => {
      const pad = "  ".repeat(indent);
      if (Array.isArray(value)) {
        emit(`${pad}${prefix}[`, id, at);
        value.forEach((item, i) => literal(item, id, `${at}[${i}]`, indent + 1, "", ","));
        emit(`${pad}]${suffix}`, id, at);
      } else if (value !== null && typeof value === "object") {
        emit(`${pad}${prefix}{`, id, at);
        for (const [key, item] of Object.entries(value)) {
          literal(item, id, at ? `${at}.${key}` : key, indent + 1, `${JSON.stringify(key)}: `, ",");
        }
        emit(`${pad}}${suffix}`, id, at);
      } else {
        emit(`${pad}${prefix}${JSON.stringify(value)}${suffix}`, id, at);
      }
    };
    const imports = new Map();
    models.forEach(({ obj, modulePath, kind }, i) => {
      const alias = `I${kind}_${imports.size}`;
      if (!imports.has(modulePath)) {
        imports.set(modulePath, alias);
      }
      literal(obj, idOf(obj), "", 0, `export const o${i}: ${imports.get(modulePath)} = `, ";");
    });
    const header = [...imports].map(([modulePath, alias]) => {
      const kind = modulePath.split("/").pop();
      return `import type { I${kind} as ${alias} } from ${JSON.stringify(modulePath)};`;
    });
    const fileName = path.join(here, "__rendered_objects__.mts"); // virtual: never written
    const sourceText = [...header, ...lines].join("\n") + "\n";
    const options = {
      noEmit: true,
      skipLibCheck: true,
      strict: false, // null for an optional field is fine for the API server; the rest is types
      target: ts.ScriptTarget.ES2022,
      module: ts.ModuleKind.Node16,
      moduleResolution: ts.ModuleResolutionKind.Node16,
      types: [],
      lib: ["lib.es5.d.ts"], // plain data: no DOM or newer built-ins needed (and faster)
    };
    const host = ts.createCompilerHost(options);
    const readFile = host.readFile.bind(host);
    const getSourceFile = host.getSourceFile.bind(host);
    const fileExists = host.fileExists.bind(host);
    host.fileExists = (f) => f === fileName || fileExists(f);
    host.readFile = (f) => (f === fileName ? sourceText : readFile(f));
    host.getSourceFile = (f, languageVersion, onError, shouldCreate) =>
      f === fileName
        ? ts.createSourceFile(f, sourceText, languageVersion, true)
        : getSourceFile(f, languageVersion, onError, shouldCreate);
    // The lib and kubernetes-models .d.ts files are parsed once and reused for the next input.
    const program = ts.createProgram([fileName], options, host, previousProgram);
    previousProgram = program;
    const checker = program.getTypeChecker();
    const byObject = new Map(models.map(({ obj }) => [idOf(obj), []]));
    const general = [];
    const where = (sourceFile, position) => {
      const { line } = sourceFile.getLineAndCharacterOfPosition(position);
      return lineInfo[line - header.length];
    };
    // Every property of every object literal against the type it is assigned to. (TypeScript's
    // own excess-property diagnostic stops at the first unknown property of each literal.)
    const sourceFile = program.getSourceFile(fileName);
    const visit = (node) => {
      if (ts.isObjectLiteralExpression(node)) {
        const contextual = checker.getContextualType(node);
        const candidates = (
          contextual?.isUnion() ? contextual.types : contextual ? [contextual] : []
        ).filter((t) => t.flags & ts.TypeFlags.Object);
        const open = candidates.some((t) => checker.getIndexInfosOfType(t).length > 0);
        if (candidates.length && !open) {
          const known = new Set(
            candidates.flatMap((t) => checker.getPropertiesOfType(t).map((p) => p.name)),
          );
          const typeName = candidates.map((t) => checker.typeToString(t)).join(" | ");
          for (const property of node.properties) {
            const name =
              property.name && ts.isStringLiteral(property.name) ? property.name.text : undefined;
            if (name === undefined || known.has(name)) continue;
            const info = where(sourceFile, property.getStart(sourceFile));
            const hint = closest(name, [...known]);
            byObject
              .get(info.id)
              .push(
                `${info.path}: unknown field (not in ${typeName})` +
                  (hint ? `; did you mean "${hint}"?` : ""),
              );
          }
        }
      }
      ts.forEachChild(node, visit);
    };
    visit(sourceFile);
    // The remaining diagnostics: wrong types, missing required fields (also caught by the schema
    // pass, here with the field's path). Excess-property diagnostics are covered above.
    const excessProperty = new Set([2353, 2561]);
    for (const diagnostic of ts.getPreEmitDiagnostics(program)) {
      if (excessProperty.has(diagnostic.code)) continue;
      const message = ts.flattenDiagnosticMessageText(diagnostic.messageText, " ");
      if (diagnostic.file?.fileName === fileName && diagnostic.start !== undefined) {
        const info = where(diagnostic.file, diagnostic.start);
        if (info) {
          byObject.get(info.id).push(`${info.path || "(object)"}: ${message}`);
          continue;
        }
      }
      general.push(message);
    }
    for (const [id, problems] of byObject) {
      check(problems.length === 0, `${id} strict fields`, problems.join("; "));
    }
    for (const message of general) {
      check(false, "strict field check", message);
    }
  }

  if (models.length) strictFieldCheck();

  // ---------------------------------------------------------------- 3. project rules
  const ofKind = (kind) => objects.filter((obj) => obj.kind === kind);
  const labelsMatch = (selector, labels = {}) => {
    // A LabelSelector (matchLabels + matchExpressions) against a label set.
    if (!selector) return false;
    const { matchLabels = {}, matchExpressions = [] } = selector;
    if (!Object.keys(matchLabels).length && !matchExpressions.length) return false; // all or none
    const exprOk = matchExpressions.every(({ key, operator, values = [] }) => {
      switch (operator) {
        case "In":
          return key in labels && values.includes(labels[key]);
        case "NotIn":
          return !(key in labels) || !values.includes(labels[key]);
        case "Exists":
          return key in labels;
        case "DoesNotExist":
          return !(key in labels);
        default:
          return false;
      }
    });
    return exprOk && Object.entries(matchLabels).every(([k, v]) => labels[k] === v);
  };
  const cpuCores = (q) => {
    const m = /^([0-9.]+)(m?)$/.exec(String(q ?? ""));
    return m ? Number(m[1]) / (m[2] ? 1000 : 1) : NaN;
  };
  const bytes = (q) => {
    const m = /^([0-9.]+)(Ki|Mi|Gi|Ti|k|M|G|T)?$/.exec(String(q ?? ""));
    const unit = {
      Ki: 2 ** 10,
      Mi: 2 ** 20,
      Gi: 2 ** 30,
      Ti: 2 ** 40,
      k: 1e3,
      M: 1e6,
      G: 1e9,
      T: 1e12,
    };
    return m ? Number(m[1]) * (m[2] ? unit[m[2]] : 1) : NaN;
  };

  const DRAIN_SECONDS = 10; // the service finishes in-flight requests for up to 10 s on SIGTERM
  const APP_PORT = 8080;
  const IMAGE_UID = 10001;

  for (const kind of ["Deployment", "Service", "HorizontalPodAutoscaler", "PodDisruptionBudget"]) {
    check(ofKind(kind).length === 1, `exactly one ${kind}`, `found ${ofKind(kind).length}`);
  }
  const namespaces = new Set(objects.map((obj) => obj.metadata?.namespace ?? ""));
  check(namespaces.size <= 1, "all objects in one namespace", [...namespaces].join(", "));
  for (const obj of objects) {
    check(
      obj.metadata?.labels?.["app.kubernetes.io/name"] === "cutcalc",
      `${idOf(obj)} carries the common label app.kubernetes.io/name=cutcalc`,
    );
  }

  const deployment = ofKind("Deployment")[0];
  if (deployment) {
    const id = idOf(deployment);
    const spec = deployment.spec ?? {};
    const pod = spec.template?.spec ?? {};
    const podLabels = spec.template?.metadata?.labels ?? {};
    const podSecurity = pod.securityContext ?? {};
    check(
      Number.isInteger(spec.replicas) && spec.replicas >= 2,
      `${id} replicas >= 2`,
      `replicas: ${JSON.stringify(spec.replicas)}`,
    );
    check(labelsMatch(spec.selector, podLabels), `${id} selector matches its pod template labels`);
    check(
      spec.strategy?.rollingUpdate?.maxUnavailable === 0 ||
        spec.strategy?.rollingUpdate?.maxUnavailable === "0%",
      `${id} rolling update keeps full capacity (maxUnavailable 0)`,
    );

    const containers = pod.containers ?? [];
    const app = containers.find((c) => c.name === "cutcalc");
    check(app !== undefined, `${id} has a container named cutcalc`);
    // Probe ports and the Service's targetPort may name a port or give its number.
    const resolvesToApp = (port) =>
      app &&
      (app.ports ?? []).some(
        (p) => p.containerPort === APP_PORT && (p.name === port || p.containerPort === port),
      );
    if (app) {
      const c = `${id} container cutcalc`;
      check(
        /^([^/]+\/)*cutcalc(:[^/@]+)?(@sha256:[0-9a-f]{64})?$/.test(app.image ?? ""),
        `${c} image is cutcalc`,
        app.image,
      );
      check(
        (app.ports ?? []).some((p) => p.name === "http" && p.containerPort === APP_PORT),
        `${c} declares port http = ${APP_PORT}`,
      );
      const probe = (name, wantPath) => {
        const get = app[name]?.httpGet;
        check(
          get?.path === wantPath && resolvesToApp(get?.port),
          `${c} ${name} is GET ${wantPath} on port ${APP_PORT}`,
          JSON.stringify(app[name] ?? null),
        );
      };
      probe("readinessProbe", "/readyz");
      probe("livenessProbe", "/healthz");
      probe("startupProbe", "/healthz");
      const startup = app.startupProbe ?? {};
      const startupWindow = (startup.periodSeconds ?? 10) * (startup.failureThreshold ?? 3);
      check(
        startupWindow >= 10 && startupWindow <= 120,
        `${c} startup probe allows 10..120 s to start`,
        `${startupWindow} s`,
      );

      const sc = app.securityContext ?? {};
      const eff = (key) => sc[key] ?? podSecurity[key];
      check(eff("runAsNonRoot") === true, `${c} runAsNonRoot`);
      check(
        eff("runAsUser") === IMAGE_UID,
        `${c} runs as the image's uid ${IMAGE_UID}`,
        `runAsUser: ${eff("runAsUser")}`,
      );
      check(sc.readOnlyRootFilesystem === true, `${c} readOnlyRootFilesystem`);
      check(sc.allowPrivilegeEscalation === false, `${c} allowPrivilegeEscalation false`);
      check(sc.privileged !== true, `${c} not privileged`);
      check(
        (sc.capabilities?.drop ?? []).includes("ALL") && !(sc.capabilities?.add ?? []).length,
        `${c} drops ALL capabilities and adds none`,
      );
      check(eff("seccompProfile")?.type === "RuntimeDefault", `${c} seccompProfile RuntimeDefault`);

      const { requests = {}, limits = {} } = app.resources ?? {};
      for (const r of ["cpu", "memory"]) {
        check(
          requests[r] !== undefined && limits[r] !== undefined,
          `${c} sets ${r} request and limit`,
        );
      }
      check(
        cpuCores(requests.cpu) <= cpuCores(limits.cpu),
        `${c} cpu request <= limit`,
        `${requests.cpu} / ${limits.cpu}`,
      );
      check(
        bytes(requests.memory) <= bytes(limits.memory),
        `${c} memory request <= limit`,
        `${requests.memory} / ${limits.memory}`,
      );

      const env = Object.fromEntries((app.env ?? []).map((e) => [e.name, e.value]));
      check(
        env.CUTCALC_HOST === "0.0.0.0",
        `${c} env CUTCALC_HOST=0.0.0.0`,
        String(env.CUTCALC_HOST),
      );
      check(
        env.CUTCALC_PORT === String(APP_PORT),
        `${c} env CUTCALC_PORT=${APP_PORT}`,
        String(env.CUTCALC_PORT),
      );
      check(
        env.CUTCALC_LOG_FORMAT === "json",
        `${c} env CUTCALC_LOG_FORMAT=json`,
        String(env.CUTCALC_LOG_FORMAT),
      );

      // Termination: preStop delay + drain must fit in the grace period.
      const preStop = app.lifecycle?.preStop;
      const command = preStop?.exec?.command ?? [];
      const preStopSeconds =
        preStop?.sleep?.seconds ??
        (/(^|\/)sleep$/.test(command[0] ?? "") ? Number(command[1]) : NaN);
      check(
        preStopSeconds >= 1 && preStopSeconds <= 15,
        `${c} preStop sleeps 1..15 s before SIGTERM`,
        JSON.stringify(preStop ?? null),
      );
      const grace = pod.terminationGracePeriodSeconds ?? 30;
      check(
        grace >= (preStopSeconds || 0) + DRAIN_SECONDS + 5,
        `${id} terminationGracePeriodSeconds covers preStop + ${DRAIN_SECONDS} s drain + 5 s`,
        `grace ${grace} s, preStop ${preStopSeconds} s`,
      );
    }

    const spreads = (pod.topologySpreadConstraints ?? []).some(
      (t) => t.topologyKey === "kubernetes.io/hostname" && labelsMatch(t.labelSelector, podLabels),
    );
    const antiAffinity = [
      ...(pod.affinity?.podAntiAffinity?.requiredDuringSchedulingIgnoredDuringExecution ?? []),
      ...(pod.affinity?.podAntiAffinity?.preferredDuringSchedulingIgnoredDuringExecution ?? []).map(
        (w) => w.podAffinityTerm,
      ),
    ].some(
      (t) => t?.topologyKey === "kubernetes.io/hostname" && labelsMatch(t.labelSelector, podLabels),
    );
    check(
      spreads || antiAffinity,
      `${id} spreads its pods across nodes (topology spread or anti-affinity by hostname)`,
    );

    const service = ofKind("Service")[0];
    if (service) {
      const sid = idOf(service);
      check((service.spec?.type ?? "ClusterIP") === "ClusterIP", `${sid} is ClusterIP`);
      check(
        labelsMatch({ matchLabels: service.spec?.selector }, podLabels),
        `${sid} selector matches the pods`,
      );
      const http = (service.spec?.ports ?? []).find((p) => p.name === "http");
      check(
        http?.port === 80 && resolvesToApp(http?.targetPort ?? http?.port),
        `${sid} port http 80 -> ${APP_PORT}`,
        JSON.stringify(http ?? null),
      );
    }

    const hpa = ofKind("HorizontalPodAutoscaler")[0];
    if (hpa) {
      const hid = idOf(hpa);
      const ref = hpa.spec?.scaleTargetRef ?? {};
      check(
        ref.apiVersion === "apps/v1" &&
          ref.kind === "Deployment" &&
          ref.name === deployment.metadata?.name,
        `${hid} targets ${id}`,
        JSON.stringify(ref),
      );
      check(
        hpa.spec?.minReplicas >= 2 && hpa.spec?.maxReplicas >= hpa.spec?.minReplicas,
        `${hid} min >= 2 and max >= min`,
        `${hpa.spec?.minReplicas}..${hpa.spec?.maxReplicas}`,
      );
      check(
        spec.replicas >= hpa.spec?.minReplicas && spec.replicas <= hpa.spec?.maxReplicas,
        `${id} replicas within the HPA's range`,
      );
      const cpu = (hpa.spec?.metrics ?? []).find(
        (m) => m.type === "Resource" && m.resource?.name === "cpu",
      );
      const util = cpu?.resource?.target?.averageUtilization;
      check(
        cpu?.resource?.target?.type === "Utilization" && util >= 50 && util <= 90,
        `${hid} scales on CPU utilisation 50..90 %`,
        JSON.stringify(cpu ?? null),
      );
      check(
        app?.resources?.requests?.cpu !== undefined,
        `${hid} has a CPU request to measure utilisation against`,
      );
    }

    const pdb = ofKind("PodDisruptionBudget")[0];
    if (pdb) {
      const pid = idOf(pdb);
      check(labelsMatch(pdb.spec?.selector, podLabels), `${pid} selector matches the pods`);
      const { minAvailable, maxUnavailable } = pdb.spec ?? {};
      check(
        (minAvailable === undefined) !== (maxUnavailable === undefined),
        `${pid} sets exactly one of minAvailable / maxUnavailable`,
      );
      // It must let a drain evict a pod at the minimum replica count, and must not allow all to go.
      const ok =
        maxUnavailable !== undefined
          ? Number.isInteger(maxUnavailable) &&
            maxUnavailable >= 1 &&
            maxUnavailable < spec.replicas
          : Number.isInteger(minAvailable) && minAvailable >= 1 && minAvailable < spec.replicas;
      check(
        ok,
        `${pid} keeps >= 1 pod and still allows one eviction at ${spec.replicas} replicas`,
        JSON.stringify({ minAvailable, maxUnavailable }),
      );
    }
  }

  return { passed, failures, ids: objects.map(idOf) };
}

// The known name nearest to a misspelled one (case-insensitive equal, or edit distance <= 2).
function closest(name, known) {
  const distance = (a, b) => {
    const row = Array.from({ length: b.length + 1 }, (_, j) => j);
    for (let i = 1; i <= a.length; i += 1) {
      let diagonal = row[0];
      row[0] = i;
      for (let j = 1; j <= b.length; j += 1) {
        const above = row[j];
        row[j] = Math.min(row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] === b[j - 1] ? 0 : 1));
        diagonal = above;
      }
    }
    return row[b.length];
  };
  let best;
  let bestDistance = 3;
  for (const candidate of known) {
    const d = candidate.toLowerCase() === name.toLowerCase() ? 0 : distance(name, candidate);
    if (d < bestDistance) {
      best = candidate;
      bestDistance = d;
    }
  }
  return best;
}

// ---------------------------------------------------------------- command line
const read = (file) => readFileSync(file === "-" ? 0 : file, "utf8");
const args = process.argv.slice(2);
const isMain = process.argv[1] && path.resolve(process.argv[1]) === fileURLToPath(import.meta.url);
if (!isMain) {
  // imported as a module: validateText() only
} else if (args[0] === "--expect-reject") {
  let ok = 0;
  let bad = 0;
  for (let i = 0; i < args.length; i += 3) {
    const [flag, message, file] = args.slice(i, i + 3);
    if (flag !== "--expect-reject" || message === undefined || file === undefined) {
      console.error(
        "usage: validate.mjs --expect-reject MESSAGE FILE [--expect-reject MESSAGE FILE]...",
      );
      process.exit(2);
    }
    const { failures } = await validateText(read(file));
    const hit = failures.find((f) => f.includes(message));
    if (hit) {
      ok += 1;
      console.log(
        `rejected as expected: ${file}: ${hit.length > 200 ? `${hit.slice(0, 200)}...` : hit}`,
      );
    } else {
      bad += 1;
      console.error(
        failures.length
          ? `REJECTED WITHOUT "${message}": ${file}:\n  ${failures.join("\n  ")}`
          : `NOT REJECTED: ${file} passed validation (expected "${message}")`,
      );
    }
  }
  console.log(`k8s-broken: ${ok} passed, ${bad} failed`);
  process.exit(bad ? 1 : 0);
} else if (args.length > 1) {
  console.error("usage: validate.mjs [FILE]   or   validate.mjs --expect-reject MESSAGE FILE ...");
  process.exit(2);
} else {
  const { passed, failures, ids } = await validateText(read(args[0] ?? "-"));
  for (const failure of failures) {
    console.error(`FAIL ${failure}`);
  }
  console.log(`k8s: validated ${ids.join(", ") || "nothing"}`);
  console.log(`k8s: ${passed} passed, ${failures.length} failed`);
  process.exit(failures.length ? 1 : 0);
}
