"""The explorer's Bokeh server, run in this process.

:func:`start_server` binds a Tornado/Bokeh server to ``host:port`` (127.0.0.1, this machine
only, unless a host is given) with one application at ``/``
(:func:`asperity.explorer.app.make_document`).  BokehJS and everything else the page loads
come from this server (``/static/``), so the explorer works without a network.  The
server accepts websocket connections only from pages it served (the origins
``host:port``, and ``localhost:port`` on the loopback address; any origin when bound to
all interfaces, ``0.0.0.0`` or ``::``).

:func:`serve` runs it until Ctrl-C (SIGINT) or SIGTERM, then stops it and returns.
"""

from __future__ import annotations

import logging
import signal
import socket
import webbrowser

from .._optional import require

__all__ = ["DEFAULT_PORT", "LOOPBACK", "start_server", "server_url", "serve", "free_port"]

#: Port of ``asperity explore`` unless ``--port`` says otherwise (a bookmark keeps working).
DEFAULT_PORT = 5006
#: The address bound unless a host is given.
LOOPBACK = "127.0.0.1"
_ALL_INTERFACES = ("0.0.0.0", "::")
_LOCAL_NAMES = ("127.0.0.1", "localhost", "::1")


def free_port(host: str = LOOPBACK, port: int = 0) -> int:
    """``port`` if it is free on ``host`` now, or (for 0) a free port the OS chooses.

    Raises
    ------
    OSError
        If ``port`` is in use or ``host`` is not an address of this machine.
    """
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)  # as the server will
        s.bind((host, port))
        return int(s.getsockname()[1])


def _origins(host: str, port: int) -> list[str]:
    if host in _ALL_INTERFACES:
        return ["*"]
    shown = f"[{host}]" if ":" in host else host
    return list(dict.fromkeys([f"{shown}:{port}"] + ([f"localhost:{port}", f"127.0.0.1:{port}"]
                                                     if host in _LOCAL_NAMES else [])))


def server_url(host: str, port: int) -> str:
    """The page's address: ``http://host:port/`` (the loopback address for a server on all interfaces)."""
    shown = LOOPBACK if host in _ALL_INTERFACES else host
    shown = f"[{shown}]" if ":" in shown else shown
    return f"http://{shown}:{port}/"


def start_server(port: int = DEFAULT_PORT, host: str = LOOPBACK):
    """A started :class:`bokeh.server.server.Server` serving the explorer at ``/`` on ``host:port``.

    Parameters
    ----------
    port : int
        TCP port, 0 for a free one (the server's ``port`` attribute says which).
    host : str
        Address to bind; the default 127.0.0.1 accepts connections from this machine only.

    Raises
    ------
    MissingDependency
        Without Bokeh (``pip install 'asperity[explore]'``).
    OSError
        If the address cannot be bound (e.g. the port is in use).
    """
    if not isinstance(host, str) or not host.strip():  # '' bound every interface under a loopback banner
        raise ValueError(f"host must be an address (127.0.0.1: this machine only; 0.0.0.0: every interface), "
                         f"got {host!r}")
    require("bokeh", purpose="the explorer", extra="explore")
    from bokeh.application import Application
    from bokeh.application.handlers.function import FunctionHandler
    from bokeh.server.server import Server

    from .app import make_document

    port = free_port(host, int(port))  # fails cleanly if taken (Tornado would leak a socket)
    # Bokeh logs a warning of its own for the wildcard origin of a server open to the network;
    # serve() says so in one line of ours instead
    wildcard = logging.getLogger("bokeh.server.util")
    level = wildcard.level
    wildcard.setLevel(logging.ERROR)
    try:
        server = Server({"/": Application(FunctionHandler(make_document))}, port=port, address=host,
                        allow_websocket_origin=_origins(host, port), num_procs=1)
    finally:
        wildcard.setLevel(level)
    server.start()
    return server


def _warm_up() -> None:
    """Compute the default view once, so the first page does not pay for imports and caches."""
    from .compute import compute
    from .state import default_state

    compute(default_state())


def serve(port: int = DEFAULT_PORT, host: str = LOOPBACK, *, open_browser: bool = True, announce=print) -> None:
    """Run the explorer until Ctrl-C (SIGINT) or SIGTERM; print its address with ``announce``.

    Parameters
    ----------
    port : int
        TCP port, 0 for a free one.
    host : str
        Address to bind (default 127.0.0.1: this machine only).
    open_browser : bool
        Open the page in the default web browser.
    announce : callable
        Receives one line with the page's address, then one when the server has stopped.
    """
    server = start_server(port, host)
    _warm_up()
    url = server_url(host, server.port)
    loop = server.io_loop
    try:
        for sig in (signal.SIGINT, signal.SIGTERM):
            loop.asyncio_loop.add_signal_handler(sig, loop.stop)
    except (NotImplementedError, AttributeError, RuntimeError):  # no loop signal handlers (Windows)
        pass
    announce(f"asperity explore: serving {url} (Ctrl-C to stop)"
             + (f"; open to the network on every interface ({host})" if host in _ALL_INTERFACES else ""))
    if open_browser:
        loop.add_callback(webbrowser.open, url)
    try:
        loop.start()
    except KeyboardInterrupt:
        pass
    finally:
        server.stop()
        for sig in (signal.SIGINT, signal.SIGTERM):
            try:
                loop.asyncio_loop.remove_signal_handler(sig)
            except (NotImplementedError, AttributeError, RuntimeError, ValueError):
                pass
    announce("asperity explore: stopped")
