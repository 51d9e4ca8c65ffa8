// A relay between the browser and the diagram server, standing for what lies between them in real
// use (a proxy, a tunnel, the network): it passes HTTP requests and WebSocket connections on, and
// can drop every WebSocket connection at once, as a network failure or a proxy's idle timeout
// does: neither the page nor the server closes them. The server answers only requests for its
// own host and port (DNS rebinding), so the relay sends the Host header the server expects.
import http from 'node:http';
import net from 'node:net';

/** Starts a relay on a free loopback port to the server of `pageUrl` (a page URL with its token). */
export async function startRelay(pageUrl) {
    const target = new URL(pageUrl);
    const upstreamHost = target.host;
    const connections = new Set();

    const server = http.createServer((request, response) => {
        const upstream = http.request(
            { host: target.hostname, port: target.port, method: request.method, path: request.url, headers: { ...request.headers, host: upstreamHost } },
            answer => {
                response.writeHead(answer.statusCode ?? 502, answer.headers);
                answer.pipe(response);
            }
        );
        upstream.on('error', () => response.destroy());
        request.pipe(upstream);
    });

    server.on('upgrade', (request, socket, head) => {
        const upstream = net.connect(Number(target.port), target.hostname);
        const connection = { socket, upstream };
        connections.add(connection);
        const drop = () => {
            connections.delete(connection);
            socket.destroy();
            upstream.destroy();
        };
        socket.on('error', drop);
        socket.on('close', drop);
        upstream.on('error', drop);
        upstream.on('close', drop);
        upstream.on('connect', () => {
            const lines = [`${request.method} ${request.url} HTTP/${request.httpVersion}`];
            for (let i = 0; i < request.rawHeaders.length; i += 2) {
                const name = request.rawHeaders[i];
                lines.push(`${name}: ${name.toLowerCase() === 'host' ? upstreamHost : request.rawHeaders[i + 1]}`);
            }
            upstream.write(lines.join('\r\n') + '\r\n\r\n');
            if (head.length > 0) {
                upstream.write(head);
            }
            socket.pipe(upstream);
            upstream.pipe(socket);
        });
    });

    await new Promise((resolve, reject) => {
        server.once('error', reject);
        server.listen(0, '127.0.0.1', resolve);
    });
    const relayed = new URL(pageUrl);
    relayed.port = String(server.address().port);

    return {
        /** The page URL through the relay. */
        url: relayed.toString(),
        /** How many WebSocket connections go through the relay now. */
        connections: () => connections.size,
        /** Cuts every WebSocket connection at once, on both sides. */
        dropConnections() {
            for (const { socket, upstream } of [...connections]) {
                socket.destroy();
                upstream.destroy();
            }
        },
        async close() {
            this.dropConnections();
            server.closeAllConnections();
            await new Promise(resolve => server.close(resolve));
        }
    };
}
