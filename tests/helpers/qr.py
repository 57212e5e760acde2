"""Reading a locker code's image as a phone camera reads it: the QR code in it, and only that.

A decoder asked for every format may also find a short 1D barcode in the printed text beside
the code (a CI run read "0612" next to the QR symbol), and it may report one symbol twice; what
must hold is one QR code, read as one text."""

from __future__ import annotations

import io

import zxingcpp
from PIL import Image


def qr_text(data: bytes, what: str) -> str:
    """The text of the one QR code in image ``data`` (``what`` names it in a failure)."""
    codes = zxingcpp.read_barcodes(
        Image.open(io.BytesIO(data)), formats=zxingcpp.BarcodeFormat.QRCode
    )
    texts = {str(code.text) for code in codes}
    assert len(texts) == 1, f"{len(texts)} QR codes in {what}: {sorted(texts)}"
    return texts.pop()
