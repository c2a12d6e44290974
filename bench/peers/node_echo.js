// Node.js peer for bench/http_bench.sh: POST <any path> answers 200 with the request body as
// application/json (a bare echo, like bench/peers/httplib_echo.cpp). No npm dependencies.
// usage: node node_echo.js PORT [HOST]     prints "listening on HOST:PORT" once bound.
'use strict';
const http = require('node:http');

const port = Number.parseInt(process.argv[2] ?? '', 10);
const host = process.argv[3] ?? '127.0.0.1';
if (!Number.isInteger(port) || port < 0 || port > 65535) {
  console.error('usage: node node_echo.js PORT [HOST]');
  process.exit(2);
}

const server = http.createServer((req, res) => {
  if (req.method !== 'POST') {
    res.writeHead(404, { 'Content-Length': 0 });
    res.end();
    return;
  }
  const chunks = [];
  req.on('data', (chunk) => chunks.push(chunk));
  req.on('end', () => {
    const body = Buffer.concat(chunks);
    res.writeHead(200, { 'Content-Type': 'application/json', 'Content-Length': body.length });
    res.end(body);
  });
});
// Same keep-alive policy as cutcalc's tuning; Node's defaults otherwise (noDelay is on).
server.keepAliveTimeout = 5000;
server.maxRequestsPerSocket = 10000;

const stop = () => {
  server.close();
  server.closeAllConnections();
  process.exit(0);
};
process.on('SIGTERM', stop);
process.on('SIGINT', stop);

server.listen({ port, host, backlog: 1024 }, () => {
  console.log(`listening on ${host}:${server.address().port}`);
});
