#import RhinoScript library
import rhinoscriptsyntax as rs
#find the closest point
u, v = rs.SurfaceClosestPoint(srf, pt)
#get closest point
closest_pt = rs.EvaluateSurface(srf, u, v)
#calculate direction from closest point to test point
dir = rs.PointCoordinates(pt) - closest_pt
#calculate surface normal
normal = rs.SurfaceNormal(srf, [u, v])
#compare the two directions using the dot product
A = dir * normal
