import Rhino
#Move to origin, find center
center = Rhino.Geometry.Point3d.Unset
if geom.Count > 0:
    bbox = geom[0].GetBoundingBox(True)
    for i in range(1, geom.Count):
        bbox.Union(geom[i].GetBoundingBox(True))
    center = bbox.Center
origin = Rhino.Geometry.Point3d.Origin
#Create move transformation matrix
m1 = Rhino.Geometry.Transform.Translation(origin - center)
#Create rotation transformation matrix
m2 = Rhino.Geometry.Transform.Rotation(angle, origin)
#Create scale transformation matrix
m3 = Rhino.Geometry.Transform.Scale(origin, scale)
#Create move back transformation matrix
m4 = Rhino.Geometry.Transform.Identity
result, m4 = m1.TryGetInverse()
#Multiply from last to first transformation
matrix = m4 * m3 * m2 * m1
#Apply transformation to all input geometry
for g in geom:
    g.Transform(matrix)
#Assign output
M = matrix
A = geom
