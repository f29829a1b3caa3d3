// A wall of 1020 blocks in running bond on a base: one gmsh model, a
// physical surface per block, every block meshed on its own (its own
// points and curves: the meshes of neighbouring blocks do not match).
//
//   gmsh -2 -format msh2 assembly-wall-1000.geo     (writes assembly-wall-1000.msh)
//
// 40 courses of blocks 1 x 0.5: even courses 25 whole blocks, odd courses
// shifted by half a block, 24 whole blocks and a half block at each end
// (26). Blocks have 2 or 3 quadrilaterals along, alternately, and one
// across. The base [-1, 26] x [-1, 0] (27 x 2 quadrilaterals) is physical
// surface 1, the blocks 2, 3, ..., 1021 course by course from the left;
// the bottom of the base is physical line 10.
Geometry.AutoCoherence = 0;   // keep the blocks' coinciding points apart
Mesh.RecombineAll      = 1;
Mesh.Algorithm         = 6;

// one rectangle [x0, x1] x [y0, y1], nx x ny quadrilaterals, physical
// surface 'tag'; 'bottom' receives its bottom curve
Macro MakeBlock
  p1 = newp; Point(p1) = {x0, y0, 0};
  p2 = newp; Point(p2) = {x1, y0, 0};
  p3 = newp; Point(p3) = {x1, y1, 0};
  p4 = newp; Point(p4) = {x0, y1, 0};
  c1 = newc; Line(c1) = {p1, p2};
  c2 = newc; Line(c2) = {p2, p3};
  c3 = newc; Line(c3) = {p3, p4};
  c4 = newc; Line(c4) = {p4, p1};
  cl = newll; Curve Loop(cl) = {c1, c2, c3, c4};
  s = news; Plane Surface(s) = {cl};
  Transfinite Curve {c1, c3} = nx + 1;
  Transfinite Curve {c2, c4} = ny + 1;
  Transfinite Surface {s};
  Recombine Surface {s};
  Physical Surface(tag) = {s};
  bottom = c1;
Return

x0 = -1; x1 = 26; y0 = -1; y1 = 0; nx = 27; ny = 2; tag = 1;
Call MakeBlock;
Physical Curve(10) = {bottom};

tag = 2;
For c In {0:39}
  y0 = 0.5 * c; y1 = y0 + 0.5; ny = 1;
  If (c % 2 == 0)
    For k In {0:24}
      x0 = k; x1 = k + 1; nx = 2 + tag % 2;
      Call MakeBlock;
      tag += 1;
    EndFor
  Else
    x0 = 0; x1 = 0.5; nx = 2 + tag % 2;
    Call MakeBlock;
    tag += 1;
    For k In {0:23}
      x0 = k + 0.5; x1 = k + 1.5; nx = 2 + tag % 2;
      Call MakeBlock;
      tag += 1;
    EndFor
    x0 = 24.5; x1 = 25; nx = 2 + tag % 2;
    Call MakeBlock;
    tag += 1;
  EndIf
EndFor
