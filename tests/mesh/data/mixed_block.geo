// Generates tests/mesh/data/mixed_block_*.msh (gmsh 4.8):
//   gmsh -2 [-bin] -format msh22|msh41 mixed_block.geo -o mixed_block_<format>[_bin].msh
//   gmsh -2 -order 2 -format msh41 mixed_block.geo -o mixed_block_order2.msh
// A block [0,2]x[0,1]: triangles on the left half, quadrangles (Recombine)
// on the right half; one physical surface, named boundary parts.
h = 0.5;
Point(1)={0,0,0,h}; Point(2)={1,0,0,h}; Point(3)={2,0,0,h};
Point(4)={2,1,0,h}; Point(5)={1,1,0,h}; Point(6)={0,1,0,h};
Line(1)={1,2}; Line(2)={2,3}; Line(3)={3,4}; Line(4)={4,5};
Line(5)={5,6}; Line(6)={6,1}; Line(7)={2,5};
Curve Loop(1)={1,7,5,6}; Plane Surface(1)={1};
Curve Loop(2)={2,3,4,-7}; Plane Surface(2)={2};
Recombine Surface{2};
Physical Curve("clamped", 3)={6};
Physical Curve("loaded", 5)={3};
Physical Curve("bottom", 7)={1,2};
Physical Surface("block", 1)={1,2};
