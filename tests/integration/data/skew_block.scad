// A block whose top and sides are skew (non-planar) quads: scadray must split each one along
// the diagonal OpenSCAD 2021.01 chooses. `nudge` lifts one top corner; the negative control
// (openscad_negative_control.sh) gives OpenSCAD a different value than scadray.
nudge = 0;
polyhedron(points = [[0, 0, 0], [20, 0, 0], [20, 20, 0], [0, 20, 0],
                     [0, 0, 10], [20, 0, 15], [20, 20, 10], [0, 20, 12 + nudge]],
           faces = [[0, 1, 2, 3], [7, 6, 5, 4], [0, 4, 5, 1], [1, 5, 6, 2], [2, 6, 7, 3],
                    [3, 7, 4, 0]]);
