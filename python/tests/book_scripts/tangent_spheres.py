import Rhino
#find a point between A and B
D = A + t * (B - A)
#find mid point between A and D
C1 = A + 0.5 * (D - A)
#find mid point between D and B
C2 = D + 0.5 * (B - D)
#find spheres radius
r1 = A.DistanceTo(C1)
r2 = B.DistanceTo(C2)
#create spheres and assign to output
S1 = Rhino.Geometry.Sphere(C1, r1)
S2 = Rhino.Geometry.Sphere(C2, r2)
