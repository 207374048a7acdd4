# Reading and writing points and meshes, generators, insertion orders.
