#Decalre a new list of points
singular_points = []
#Examine all trims in the input brep
for trim in srf.Trims:
    #Null edge of a trim indicates a singularity
    if trim.Edge == None:
        #Find the 2D parameter space point at trim start or end
        pt2d = trim.PointAtStart
        #Evaluate trim end point on the object surface
        pt3d = trim.Face.PointAt(pt2d.X, pt2d.Y)
        #Add 3D point to the list of singular points
        singular_points.append(pt3d)
#Asign output
A = singular_points
