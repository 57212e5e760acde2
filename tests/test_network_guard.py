import socket

import pytest

from netguard import NetworkAccessError


def test_connect_beyond_loopback_fails() -> None:
    s = socket.socket()
    try:
        with pytest.raises(NetworkAccessError):
            s.connect(("192.0.2.1", 80))
    finally:
        s.close()


def test_resolving_a_public_name_fails() -> None:
    with pytest.raises(NetworkAccessError):
        socket.getaddrinfo("example.com", 443)


def test_loopback_is_allowed() -> None:
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen()
    client = socket.socket()
    try:
        client.connect(server.getsockname())
    finally:
        client.close()
        server.close()
