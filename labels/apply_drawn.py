#!/usr/bin/env python3
"""Writes what was drawn by hand for a frame (labels/drawn/<half>/<frame>.txt) into its label file
(labels/real/<half>/<frame>.yaml), keeping the label's gravity and projector unless the drawing states
a gravity. The label tool then fits, refines and recomputes the best rectangle (remake.sh).

Drawing lines:  N <note>
                G gx,gy,gz                       (gravity stated by hand)
                S <surface>/<region>|x,y x,y ...  (a region of a usable surface, depth pixels)
                O <obstacle>|x,y x,y ...          (an obstacle, as drawn)
                C <colour note>                   (judged on the registered rgb.png: writes a colour section)
                U <name>|<why>|x,y x,y ...        (unsuitable by its colour although depth calls it free;
                                                   why: textured, dark, saturated or glare)
                K <obstacle>;<obstacle>           (obstacles kept as drawn, not shrunk to the depth by the
                                                   label tool's --refine: read by remake.sh, not here)
usage: apply_drawn.py <drawn.txt> <label.yaml>
"""
import re
import sys


def polygon(points):
    return '[' + ', '.join('[%s]' % p.replace(',', ', ') for p in points.split()) + ']'


def main(drawn, label):
    text = open(label).read()
    frame = re.search(r'^frame: (.*)$', text, re.M).group(1)
    surfaces, order, obstacles, note, gravity = {}, [], [], None, None
    colour_note, unsuitable = None, []
    for line in open(drawn):
        line = line.rstrip('\n')
        if not line.strip():
            continue
        kind, rest = line[0], line[2:]
        if kind == 'N':
            note = rest
        elif kind == 'G':
            gravity = rest
        elif kind == 'C':
            colour_note = rest
        elif kind == 'K':
            continue
        elif kind == 'U':
            name, why, points = rest.split('|')
            unsuitable.append((name, why, polygon(points)))
        else:
            name, points = rest.split('|')
            if kind == 'S':
                surface, region = (name.split('/', 1) + [''])[:2]
                if surface not in surfaces:
                    surfaces[surface] = []
                    order.append(surface)
                surfaces[surface].append((region, polygon(points)))
            elif kind == 'O':
                obstacles.append((name, polygon(points)))
            else:
                sys.exit('%s: unknown line kind %r' % (drawn, kind))
    out = 'surfaces:\n' + ('' if order else '  []\n')
    for s in order:
        out += '  - name: %s\n    regions:\n' % s
        for region, poly in surfaces[s]:
            out += ('      - name: %s\n        polygon: %s\n' % (region, poly)) if region else '      - polygon: %s\n' % poly
    out += 'obstacles:\n' + ('' if obstacles else '  []\n')
    for name, poly in obstacles:
        out += '  - name: %s\n    polygon: %s\n' % (name, poly)
    if unsuitable and colour_note is None:
        sys.exit('%s: U lines need a C line (the colour judgement)' % drawn)
    if colour_note is not None:
        out_colour = 'colour:\n  note: "%s"\n  unsuitable:%s\n' % (colour_note.replace('"', "'"),
                                                                    '' if unsuitable else ' []')
        for name, why, poly in unsuitable:
            out_colour += '    - name: %s\n      why: %s\n      polygon: %s\n' % (name, why, poly)
        out_colour += '  best:\n    found: false\n'
    else:
        out_colour = ''
    text = re.sub(r'surfaces:\n.*', out + 'best:\n  found: false\n' + out_colour, text, flags=re.S)
    text = re.sub(r'^note: .*\n', '', text, flags=re.M)
    if note:
        text = text.replace('frame: %s\n' % frame, 'frame: %s\nnote: "%s"\n' % (frame, note.replace('"', "'")), 1)
    if gravity:
        text = re.sub(r'gravity:\n  source: \w+\n  vector: .*\n',
                      'gravity:\n  source: stated\n  vector: [%s]\n' % gravity.replace(',', ', '), text)
    open(label, 'w').write(text)


if __name__ == '__main__':
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
