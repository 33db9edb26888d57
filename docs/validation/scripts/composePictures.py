#!/usr/bin/python3
"""Lay snapshots of renderParticles out in one picture for the docs.

    composePictures.py OUT.jpg TITLE LEFT,TOP,RIGHT,BOTTOM IMAGE=LABEL ...

crops each IMAGE (renderParticles' default 1600x900) to the box, puts them
two to a row under the TITLE, each with its LABEL, and the colour bars of
the first image below them; the whole scaled to 80 % and saved as JPEG.
(Debian: python3-pil.)
"""
import sys

from PIL import Image, ImageDraw, ImageFont

BARS = (150, 770, 1450, 880)        # the colour bars in a 1600x900 picture


def compose(out, title, box, images):
    ims = [(Image.open(path).convert("RGB"), label) for path, label in images]
    w, h = box[2] - box[0], box[3] - box[1]
    rows = (len(ims) + 1)//2
    bar = ims[0][0].crop(BARS)
    page = Image.new("RGB", (2*w, rows*h + bar.size[1] + 40), "white")
    font = ImageFont.truetype(
        "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", 26)
    d = ImageDraw.Draw(page)
    for k, (im, label) in enumerate(ims):
        x, y = (k % 2)*w, (k//2)*h + 40
        page.paste(im.crop(box), (x, y))
        d.text((x + 20, y + 10), label, fill="black", font=font)
    d.text((20, 5), title, fill="black", font=font)
    page.paste(bar, ((2*w - bar.size[0])//2, rows*h + 40))
    page = page.resize((int(page.size[0]*0.8), int(page.size[1]*0.8)),
                       Image.LANCZOS)
    page.save(out, quality=88, optimize=True)
    print(out)


if __name__ == "__main__":
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    box = tuple(int(v) for v in sys.argv[3].split(","))
    if len(box) != 4:
        sys.exit("the box: LEFT,TOP,RIGHT,BOTTOM in pixels")
    compose(sys.argv[1], sys.argv[2], box,
            [a.partition("=")[::2] for a in sys.argv[4:]])
