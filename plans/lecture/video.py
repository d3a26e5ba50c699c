"""Animations for slides: the frames as a GIF (Pillow) or an MP4 (H.264 by the ffmpeg of imageio-ffmpeg).

The frames are rasterised by matplotlib's Agg (:meth:`plans.drawing.frames.CycleFrames.rgb`);
nothing is fetched from a network.

* GIF: Pillow, which matplotlib already needs (``pip install pillow``); each
  frame reduced to 256 colours, looping, one cycle in
  :data:`plans.lecture.page.SECONDS_PER_CYCLE` seconds.
* MP4: the ``imageio-ffmpeg`` package from PyPI, whose wheel ships an ffmpeg
  binary (``pip install imageio-ffmpeg``, or ``pip install "plans[animate]"``);
  H.264 in yuv420p, which slides (PowerPoint, Impress, Keynote, browsers) play,
  written bit-exact (no encoder version or date in the file), so the same
  frames give the same bytes.

Both return the file's bytes; :mod:`plans.lecture` writes them atomically.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np

from ..errors import OutputError

__all__ = ["gif_bytes", "mp4_bytes", "even_frame", "MP4_INSTALL"]

#: What to do when the MP4 encoder is missing.
MP4_INSTALL = 'an MP4 needs the ffmpeg that the imageio-ffmpeg package ships: pip install imageio-ffmpeg (or pip install "plans[animate]")'
#: Frames of an MP4 are padded to a multiple of this many pixels (H.264's macroblock).
BLOCK = 16


def even_frame(pixels: np.ndarray, block: int = BLOCK) -> np.ndarray:
    """*pixels* (height, width, 3) padded with white on the right and at the bottom to multiples of *block*."""
    h, w = pixels.shape[:2]
    H, W = -(-h // block) * block, -(-w // block) * block
    if (H, W) == (h, w):
        return pixels
    out = np.full((H, W, 3), 255, dtype=np.uint8)
    out[:h, :w] = pixels
    return out


def gif_bytes(frames, seconds_per_frame: float) -> bytes:
    """A looping GIF of *frames* (arrays of uint8, height × width × 3, all the same size)."""
    import io

    from PIL import Image

    images = [Image.fromarray(np.ascontiguousarray(f)).quantize(colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE) for f in frames]
    if not images:
        raise ValueError("no frames to write")
    buffer = io.BytesIO()
    duration = max(20, int(round(1000 * seconds_per_frame / 10.0)) * 10)  # GIF counts hundredths of a second
    images[0].save(buffer, format="GIF", save_all=True, append_images=images[1:], duration=duration, loop=0, disposal=1)
    return buffer.getvalue()


def mp4_bytes(frames, fps: float, *, path_for_errors: str = "animation.mp4") -> bytes:
    """An H.264 MP4 of *frames* at *fps* frames per second (sizes padded to multiples of 16)."""
    try:
        import imageio_ffmpeg
    except ImportError:
        raise OutputError(f"{path_for_errors}: {MP4_INSTALL}") from None
    frames = [even_frame(f) for f in frames]
    if not frames:
        raise ValueError("no frames to write")
    h, w = frames[0].shape[:2]
    with tempfile.TemporaryDirectory(prefix="plans-mp4-") as tmp:
        target = Path(tmp) / "animation.mp4"
        writer = imageio_ffmpeg.write_frames(
            str(target), (w, h), fps=fps, codec="libx264", pix_fmt_in="rgb24", pix_fmt_out="yuv420p", quality=None,
            macro_block_size=1, ffmpeg_log_level="error",
            output_params=["-crf", "20", "-preset", "medium", "-tune", "stillimage", "-threads", "1",
                           "-fflags", "+bitexact", "-flags:v", "+bitexact", "-map_metadata", "-1", "-movflags", "+faststart"],
        )
        writer.send(None)  # start the encoder
        for f in frames:
            writer.send(np.ascontiguousarray(f))
        writer.close()
        return target.read_bytes()
