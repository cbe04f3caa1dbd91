"""A TCP relay that holds every byte for DELAY_MS each way before passing it on: an emulated
link's latency where the kernel has no tc netem (CONFIG_NET_SCH_NETEM unset).

  python3 delay_relay.py LISTEN_HOST TARGET_HOST TARGET_PORT DELAY_MS

Prints the port it listens on (chosen by the system), then relays until killed. Order is kept;
only latency is added, not loss or a bandwidth limit.
"""
import asyncio
import socket
import sys
import time


def no_delay(writer):
    sock = writer.get_extra_info("socket")
    if sock is not None:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)


async def pump(reader, writer, delay):
    queue = asyncio.Queue()

    async def take():
        while True:
            data = await reader.read(1 << 16)
            queue.put_nowait((time.monotonic() + delay, data))
            if not data:
                return

    async def give():
        while True:
            due, data = await queue.get()
            wait = due - time.monotonic()
            if wait > 0:
                await asyncio.sleep(wait)
            if not data:
                writer.close()
                return
            writer.write(data)
            await writer.drain()

    await asyncio.gather(take(), give())


async def main(listen_host, target_host, target_port, delay_ms):
    delay = delay_ms / 1000.0

    async def relay(client_reader, client_writer):
        try:
            server_reader, server_writer = await asyncio.open_connection(target_host, target_port)
        except OSError:
            client_writer.close()
            return
        no_delay(client_writer)
        no_delay(server_writer)
        await asyncio.gather(pump(client_reader, server_writer, delay),
                             pump(server_reader, client_writer, delay), return_exceptions=True)
        client_writer.close()
        server_writer.close()

    server = await asyncio.start_server(relay, listen_host, 0)
    print(server.sockets[0].getsockname()[1], flush=True)
    async with server:
        await server.serve_forever()


if __name__ == "__main__":
    asyncio.run(main(sys.argv[1], sys.argv[2], int(sys.argv[3]), float(sys.argv[4])))
