"""Serving the simulated device (docs/conformance.md section 9, "Several hosts"): over a pty (one host,
a serial line) or TCP, where several hosts are served at once, as a device's serial port behind
a network bridge with several clients (ser2net-style):

- every connected host receives every byte the device sends (its data and its replies to any
  host's commands), as on a shared line;
- the bytes of each host are framed on their own (each host its own parser): half a packet from
  one host never merges with another's bytes, and the device takes each host's packets, NMEA
  sentences and RTCM3 frames whole;
- at most MAX_HOSTS hosts at once: the next connection is closed at once (a line on stderr);
- each host has its own bounded output backlog: a host that does not read loses what does not fit
  (as a device's overrun output buffer), is not read after DEAF seconds and is disconnected after
  STALL seconds (a line on stderr), and never holds up the device or the other hosts; a host
  leaving changes nothing for the others.

The settings persist across hosts, as a device's do; while no host is connected the device
streams on into nothing, so the first host's data starts at its arrival, and a host joining
others receives the stream from its arrival on.
"""

from __future__ import annotations

import errno
import os
import select
import socket
import sys
import time
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

from ..codec.framing import Parser
from . import Chunk, Simulator
from . import status as sim_status

MAX_HOSTS = 8  # TCP hosts served at once (the next connection is closed at once)
LISTEN_BACKLOG = 16  # connections not yet accepted (more: the kernel makes them retry)


def _baud_codes() -> Dict[int, int]:
    try:
        import termios
    except ImportError:
        return {}
    return {getattr(termios, n): int(n[1:]) for n in dir(termios) if n[:1] == "B" and n[1:].isdigit()}


BAUD_CODES = _baud_codes()


class Link:
    """One byte pipe to a host (a pty master or an accepted TCP connection), non-blocking: what
    the host does not read yet waits in `backlog`, up to BACKLOG bytes (more is dropped, as a
    device's output buffer overruns). A TCP host that has read nothing for STALL seconds while
    output waits, or whose connection fails a write, is `dead`: the serving loop closes it. Each
    link has its own `parser` (the framing of what its host sends) and, with --replay, its own
    `queue` of the capture's packets, sent from its arrival (`started`)."""

    BACKLOG = 1 << 18
    FULL_BACKLOG = 1 << 15  # with --stream-full: a device's output buffer, not a pipe's
    STALL = 5.0
    DEAF = 1.0
    SNDBUF = 1 << 16

    def __init__(self, fd: int, sock: Optional[socket.socket] = None, slave: Optional[int] = None) -> None:
        self.fd = fd
        self.sock = sock
        self.slave = slave  # a pty's slave side: the host's line settings (its baud rate)
        self.baud: Optional[int] = None  # the device's rate once a command changed it
        self.backlog = bytearray()
        self.progress = time.monotonic()  # the last time the host took bytes (or had none waiting)
        self.dead = False
        self.parser = Parser()
        self.queue: List[Tuple[float, bytes]] = []
        self.started = time.monotonic()
        os.set_blocking(fd, False)

    def stalled(self, now: float) -> bool:
        """Whether a TCP host has read nothing for STALL seconds while output waits."""
        return self.sock is not None and bool(self.backlog) and now - self.progress > self.STALL

    def deaf(self, now: float) -> bool:
        """Whether a TCP host has read nothing for DEAF seconds while output waits: its commands
        are not read meanwhile (their replies could not be sent; a host flooding commands without
        reading gets no more of the simulator's time)."""
        return self.sock is not None and bool(self.backlog) and now - self.progress > self.DEAF

    def mismatched(self) -> bool:
        """Whether the host's line runs at another rate than the device's (after a baud change on
        a pty; before one, any rate works): bytes then arrive as garbage on both sides."""
        if self.baud is None or self.slave is None:
            return False
        import termios

        try:
            speed = termios.tcgetattr(self.slave)[5]
        except termios.error:
            return False
        return BAUD_CODES.get(speed) != self.baud

    def write(self, data: bytes) -> None:
        if not self.backlog:
            self.progress = time.monotonic()
        if len(self.backlog) + len(data) <= self.BACKLOG:
            self.backlog += data
        self.flush()

    def flush(self) -> None:
        while self.backlog and not self.dead:
            chunk = bytes(self.backlog)
            if self.mismatched():  # read at the host's rate when it leaves, not when it was queued
                chunk = bytes((b ^ 0x5A) for b in chunk)
            try:
                n = os.write(self.fd, chunk)
            except BlockingIOError:
                return
            except OSError as e:
                if self.sock is None and e.errno == errno.EIO:  # a pty whose host closed it: keep the bytes
                    return
                self.backlog.clear()  # a host that has gone (EPIPE, ECONNRESET, ...): closed by the loop
                self.dead = self.sock is not None
                return
            if n > 0:
                self.progress = time.monotonic()
            del self.backlog[:n]

    def read(self) -> Optional[bytes]:
        """The bytes the host sent (b"": none yet), None when a TCP host has gone."""
        try:
            data = os.read(self.fd, 65536)
        except BlockingIOError:
            return b""
        except OSError as e:
            if e.errno == errno.EIO and self.sock is None:
                return b""
            return None
        if not data and self.sock is not None:
            return None
        if data and self.mismatched():
            return bytes((b ^ 0x5A) for b in data)
        return data

    def close(self) -> None:
        if self.sock is not None:
            self.sock.close()
            return
        for fd in (self.fd, self.slave):
            if fd is not None:
                try:
                    os.close(fd)
                except OSError:
                    pass


def serve(
    listen: str,
    sim: Optional[Simulator],
    replay: Optional[List[Tuple[float, bytes]]] = None,
    out: Any = None,
    replug: Sequence[Tuple[float, float]] = (),
    start_baud: Optional[int] = None,
) -> None:
    """Serves `sim` (or a replay) on `listen` ("pty", "pty:PATH" or "tcp:HOST:PORT") until
    terminated; the first line written to `out` (stdout) is the address to connect to (with
    pty:PATH, PATH: a symbolic link to the pty's slave side, replaced when the pty is reopened). A
    pty's slave side stays open here too, so its master never reads end-of-file between two hosts.

    `replug`: (START, END) pairs in seconds of real time since the first bytes a host sent: at
    START the port goes away (the pty is closed and PATH removed; TCP: every connection and the
    listening socket are closed), at END a fresh one comes back (a new pty, PATH pointing to it,
    with plain pty its path printed as a further line; TCP: listening on the same port again). The
    device keeps its settings and streams on meanwhile, as a device whose USB cable is re-plugged.
    `start_baud`: the pty serves at that rate only from the start (the device's port was set to it).
    """
    out = out or sys.stdout
    backlog = Link.FULL_BACKLOG if sim is not None and sim.full else Link.BACKLOG
    if listen == "pty" or listen.startswith("pty:"):
        path = listen[4:] or None
        if path is not None and os.path.lexists(path) and not os.path.islink(path):
            raise ValueError(f"bad --listen {listen!r}: {path} exists and is not a symbolic link")

        def open_pty(previous: Optional[Link]) -> Link:
            import tty

            master, slave = os.openpty()
            tty.setraw(slave)
            name = os.ttyname(slave)
            if path is not None:
                tmp = f"{path}.{os.getpid()}.tmp"
                if os.path.lexists(tmp):
                    os.unlink(tmp)
                os.symlink(name, tmp)
                os.replace(tmp, path)
            if previous is None or path is None:
                print(path or name, file=out, flush=True)
            link = Link(master, slave=slave)
            link.BACKLOG = backlog
            link.baud = previous.baud if previous is not None else start_baud
            return link

        def close_pty(link: Link) -> None:
            if path is not None and os.path.islink(path):
                os.unlink(path)
            link.close()

        _Serving(sim, replay, replug, backlog, reopen=open_pty, unplug=close_pty).run(open_pty(None), None)
        return
    if not listen.startswith("tcp:"):
        raise ValueError(f"bad --listen {listen!r} (expected pty, pty:PATH or tcp:HOST:PORT)")
    host, _, port = listen[4:].rpartition(":")
    host = host.strip("[]") or "127.0.0.1"
    if not port.isdigit() or int(port) > 65535:
        raise ValueError(f"bad --listen {listen!r} (expected tcp:HOST:PORT; port 0 picks a free one)")
    family = socket.AF_INET6 if ":" in host else socket.AF_INET

    def listen_on(number: int) -> socket.socket:
        server = socket.socket(family, socket.SOCK_STREAM)
        server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        # the connections' send buffer (inherited): a host that does not read holds at most this
        # much in the kernel beside the simulator's own bounded backlog
        server.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, Link.SNDBUF)
        server.bind((host, number))
        server.listen(LISTEN_BACKLOG)
        return server

    server = listen_on(int(port))
    bound = server.getsockname()[1]
    shown = f"[{host}]" if family == socket.AF_INET6 else host
    print(f"tcp:{shown}:{bound}", file=out, flush=True)
    _Serving(sim, replay, replug, backlog, relisten=lambda: listen_on(bound)).run(None, server)


def _note(text: str) -> None:
    print(f"{__name__}: {text}", file=sys.stderr, flush=True)


class _Serving:
    """The serving loop: the device's output (`pending`, replies and data at their times) goes to
    every link; each link's bytes are fed to the device through the link's own parser. `replug`
    (see serve): the pty is closed with `unplug(link)` and reopened with `reopen(link)`; TCP:
    every connection and the listening socket are closed and `relisten()` listens again."""

    def __init__(
        self,
        sim: Optional[Simulator],
        replay: Optional[List[Tuple[float, bytes]]],
        replug: Sequence[Tuple[float, float]],
        backlog: int,
        reopen: Optional[Callable[[Optional[Link]], Link]] = None,
        unplug: Optional[Callable[[Link], None]] = None,
        relisten: Optional[Callable[[], socket.socket]] = None,
    ) -> None:
        self.sim = sim
        self.replay = list(replay or [])
        self.plugs = sorted(replug)
        self.backlog = backlog
        self.reopen, self.unplug, self.relisten = reopen, unplug, relisten
        self.links: List[Link] = []
        self.server: Optional[socket.socket] = None
        self.pending: List[Chunk] = []  # what the device sends, at its times
        self.first_bytes: Optional[float] = None  # when a host first sent something: replug times count from it
        self.unplugged: Optional[Tuple[float, Optional[Link]]] = None  # (back at, the closed pty's link)

    # ------------------------------------------------------------------ hosts
    def add(self, link: Link) -> None:
        link.BACKLOG = self.backlog
        if self.sim is not None and not self.links:
            self.sim.skip(time.monotonic())  # nobody read the device's output until now
        link.started = time.monotonic()
        link.queue = list(self.replay)  # a replay: the whole capture, from its arrival
        self.links.append(link)

    def drop(self, link: Link) -> None:
        link.close()
        self.links.remove(link)
        if not self.links:
            self.pending.clear()  # replies scheduled later (--delay, --split): nobody is left to read them

    def accept(self) -> None:
        assert self.server is not None
        try:
            conn, peer = self.server.accept()
        except OSError:  # the host left before it was served (ECONNABORTED, ...)
            return
        if len(self.links) >= MAX_HOSTS:
            _note(f"{MAX_HOSTS} hosts are connected: a connection from {_peer(peer)} closed")
            conn.close()
            return
        try:
            conn.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        except OSError:  # ... or reset its connection already
            conn.close()
            return
        self.add(Link(conn.fileno(), conn))

    # ------------------------------------------------------------------ the port
    def replug_due(self, now: float) -> None:
        """The port goes away (the next --replug START) or comes back (its END)."""
        if self.plugs and self.first_bytes is not None and self.unplugged is None:
            if now >= self.first_bytes + self.plugs[0][0]:
                begin, end = self.plugs.pop(0)
                self.pending.clear()
                closed = self.links[0] if self.links and self.links[0].sock is None else None
                if self.server is not None:  # first: no host connects between the two
                    self.server.close()
                    self.server = None
                for link in list(self.links):
                    if link.sock is None and self.unplug is not None:
                        self.unplug(link)
                    else:
                        link.close()
                self.links.clear()
                self.unplugged = (self.first_bytes + end, closed)
        if self.unplugged is not None and now >= self.unplugged[0]:
            if self.reopen is not None:
                self.add(self.reopen(self.unplugged[1]))
            elif self.relisten is not None:
                self.server = self.relisten()
            self.unplugged = None

    # ------------------------------------------------------------------ output
    def write(self, chunk: bytes) -> None:
        """Every host receives what the device sends (a shared line)."""
        for link in self.links:
            link.write(chunk)

    def deliver(self, now: float) -> None:
        """The device's output due by `now`, to every host; a replay's packets to each host."""
        sim = self.sim
        if sim is not None:
            self.pending.extend(sim.poll(now))
        self.pending.sort(key=lambda c: c[0])
        due = 0
        while due < len(self.pending) and self.pending[due][0] <= now:
            due += 1
        for when, chunk in self.pending[:due]:
            sim_status.write(self, chunk, sim)  # counted once: the device wrote it once
            while sim is not None and sim.baud_changes and 0 <= sim.baud_changes[0][0] <= when:
                rate = sim.baud_changes.pop(0)[1]
                for link in self.links:
                    link.baud = rate
        del self.pending[:due]
        # replies scheduled later (--delay, --split) wait here: at most a backlog's worth
        while sum(len(c) for _, c in self.pending) > self.backlog:
            self.pending.pop()
        for link in self.links:
            while link.queue and link.started + link.queue[0][0] <= now:
                link.write(link.queue.pop(0)[1])

    def wakeup(self, now: float) -> float:
        """Seconds until something is due (at most 0.5)."""
        wake = [c[0] for c in self.pending[:1]]
        if self.sim is not None and self.links:
            w = self.sim.next_wakeup(now)
            if w is not None:
                wake.append(w)
        for link in self.links:
            if link.queue:
                wake.append(link.started + link.queue[0][0])
            if link.sock is not None and link.backlog:
                wake.append(link.progress + link.STALL + 0.01)
        if self.plugs and self.first_bytes is not None:
            wake.append(self.first_bytes + self.plugs[0][0])
        return min(0.5, max(0.0, min(wake) - now)) if wake else 0.5

    # ------------------------------------------------------------------ input
    def take(self, link: Link) -> None:
        """What `link`'s host sent, fed to the device through the host's own parser."""
        data = link.read()
        if data is None:
            self.drop(link)
            return
        if data and self.first_bytes is None:
            self.first_bytes = time.monotonic()
        if data and self.sim is not None:
            self.pending.extend(self.sim.feed(data, time.monotonic(), link.parser))
        elif not data and link.sock is None:
            time.sleep(0.01)  # a pty without a host reports EIO at once: do not spin

    # ------------------------------------------------------------------ the loop
    def run(self, link: Optional[Link], server: Optional[socket.socket]) -> None:
        if link is not None:
            self.add(link)
        self.server = server
        while True:
            now = time.monotonic()
            for link in [x for x in self.links if x.sock is not None and (x.dead or x.stalled(now))]:
                if not link.dead:
                    _note(f"a host read nothing for {link.STALL:g} s: disconnected")
                self.drop(link)  # a TCP host that has gone or stalled: the others go on
            self.replug_due(now)
            if self.unplugged is not None:
                if self.sim is not None:
                    self.sim.poll(now)  # the device streams on into a port nobody reads
                time.sleep(min(0.01, max(0.0, self.unplugged[0] - now)))
                continue
            if self.links:
                self.deliver(now)
            elif self.sim is not None:
                self.sim.skip(now)  # no host connected: nobody reads what the device sends
            timeout = self.wakeup(now)
            readers = [x.fd for x in self.links if not x.deaf(now)]
            if self.server is not None:
                readers.append(self.server.fileno())
            writers = [x.fd for x in self.links if x.backlog]
            ready, writable, _ = select.select(readers, writers, [], timeout)
            for link in self.links:
                if link.fd in writable:
                    link.flush()
            if self.server is not None and self.server.fileno() in ready:
                self.accept()
            for link in [x for x in self.links if x.fd in ready]:
                self.take(link)


def _peer(peer: Any) -> str:
    return f"{peer[0]}:{peer[1]}" if isinstance(peer, tuple) and len(peer) >= 2 else str(peer)
