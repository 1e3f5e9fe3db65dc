// What compute voxelization reads of an actor (SceneBuffers.h), without a GL context: the
// triangles VTK's index buffers draw (polygons as fans, strips alternating, lines and
// vertices none), cell colours by VTK's cell numbering (vertices, lines, polygons, strips),
// per-point colours, positions relative to the bounds' centre, damaged indices left out, and
// which actors keep the raster path.
#include "SceneBuffers.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkCamera.h"
#include "vtkFollower.h"
#include "vtkNew.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace
{
/// Points 0-3 a unit quad at z = 10, 4-6 a triangle, 7-11 a strip; one vertex and one line
/// ahead of the polygons, as cells 0 and 1.
struct Mixed
{
  vtkNew<vtkPolyData> Data;
  vtkNew<vtkOpenGLPolyDataMapper> Mapper;
  vtkNew<vtkOpenGLActor> Actor;

  Mixed()
  {
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 12; ++i)
    {
      points->InsertNextPoint(i % 2, i / 2, 10.0);
    }
    this->Data->SetPoints(points);
    vtkNew<vtkCellArray> verts;
    verts->InsertNextCell({ 0 });
    vtkNew<vtkCellArray> lines;
    lines->InsertNextCell({ 0, 1 });
    vtkNew<vtkCellArray> polys;
    polys->InsertNextCell({ 0, 1, 2, 3 });
    polys->InsertNextCell({ 4, 5, 6 });
    polys->InsertNextCell({ 4, 5, 99 }); // an index beyond the points
    vtkNew<vtkCellArray> strips;
    strips->InsertNextCell({ 7, 8, 9, 10, 11 });
    this->Data->SetVerts(verts);
    this->Data->SetLines(lines);
    this->Data->SetPolys(polys);
    this->Data->SetStrips(strips);
    this->Mapper->SetInputData(this->Data);
    this->Actor->SetMapper(this->Mapper);
  }

  /// Direct RGBA colours: `value` + 10 * index per tuple.
  vtkUnsignedCharArray* Colors(vtkIdType tuples, unsigned char value)
  {
    auto* colors = vtkUnsignedCharArray::New();
    colors->SetNumberOfComponents(4);
    for (vtkIdType i = 0; i < tuples; ++i)
    {
      const unsigned char c = static_cast<unsigned char>(value + 10 * i);
      colors->InsertNextTuple4(c, c, c, 255);
    }
    this->Mapper->SetColorModeToDirectScalars();
    return colors;
  }
};

std::uint32_t Gray(unsigned char c)
{
  return c | (c << 8) | (c << 16) | (255u << 24);
}
}

TEST(SceneBuffers, TrianglesAsVTKDrawsThem)
{
  Mixed m;
  voxelgi::TriangleArrays arrays;
  std::string why;
  ASSERT_TRUE(voxelgi::ReadTriangles(m.Actor, m.Data, arrays, why));
  EXPECT_EQ(arrays.Colors, voxelgi::TriangleColors::Actor);
  const std::vector<std::uint32_t> expected = {
    0, 1, 2, 0, 2, 3, // the quad as a fan
    4, 5, 6,          // the triangle; the damaged one left out
    7, 8, 9, 8, 10, 9, 9, 10, 11 // the strip, every other one turned
  };
  EXPECT_EQ(arrays.Indices, expected);
  EXPECT_TRUE(arrays.CellColors.empty()); // coloured by the actor
  // Positions relative to the bounds' centre (0.5, 2.5, 10).
  ASSERT_EQ(arrays.Vertices.size(), 12u);
  EXPECT_DOUBLE_EQ(arrays.Shift[2], 10.0);
  EXPECT_FLOAT_EQ(arrays.Vertices[11].Position[0], 0.5f);
  EXPECT_FLOAT_EQ(arrays.Vertices[11].Position[1], 2.5f);
  EXPECT_FLOAT_EQ(arrays.Vertices[11].Position[2], 0.0f);
}

TEST(SceneBuffers, CellColorsByVTKCellNumbering)
{
  Mixed m;
  vtkUnsignedCharArray* colors = m.Colors(6, 5); // vertex, line, 3 polygons, strip
  m.Data->GetCellData()->SetScalars(colors);
  colors->Delete();
  voxelgi::TriangleArrays arrays;
  std::string why;
  ASSERT_TRUE(voxelgi::ReadTriangles(m.Actor, m.Data, arrays, why));
  EXPECT_EQ(arrays.Colors, voxelgi::TriangleColors::Cell);
  ASSERT_EQ(arrays.Indices.size(), 18u);
  ASSERT_EQ(arrays.CellColors.size(), 6u); // one per triangle, the damaged one left out
  EXPECT_EQ(arrays.CellColors[0], Gray(25)); // the quad: cell 2
  EXPECT_EQ(arrays.CellColors[1], Gray(25));
  EXPECT_EQ(arrays.CellColors[2], Gray(35)); // the triangle: cell 3
  EXPECT_EQ(arrays.CellColors[3], Gray(55)); // the strip: cell 5
  EXPECT_EQ(arrays.CellColors[5], Gray(55));
}

TEST(SceneBuffers, PointColors)
{
  Mixed m;
  vtkUnsignedCharArray* colors = m.Colors(12, 0);
  m.Data->GetPointData()->SetScalars(colors);
  colors->Delete();
  voxelgi::TriangleArrays arrays;
  std::string why;
  ASSERT_TRUE(voxelgi::ReadTriangles(m.Actor, m.Data, arrays, why));
  EXPECT_EQ(arrays.Colors, voxelgi::TriangleColors::Vertex);
  EXPECT_EQ(arrays.Vertices[7].Color, Gray(70));
  m.Mapper->ScalarVisibilityOff();
  ASSERT_TRUE(voxelgi::ReadTriangles(m.Actor, m.Data, arrays, why));
  EXPECT_EQ(arrays.Colors, voxelgi::TriangleColors::Actor);
}

TEST(SceneBuffers, FieldDataColorsRefused)
{
  Mixed m;
  vtkUnsignedCharArray* colors = m.Colors(1, 0);
  colors->SetName("tint");
  m.Data->GetFieldData()->AddArray(colors);
  colors->Delete();
  m.Mapper->SetScalarModeToUseFieldData();
  m.Mapper->SelectColorArray("tint");
  voxelgi::TriangleArrays arrays;
  std::string why;
  EXPECT_FALSE(voxelgi::ReadTriangles(m.Actor, m.Data, arrays, why));
  EXPECT_EQ(why, "colours from field data");
}

TEST(SceneBuffers, WhatKeepsTheRasterPath)
{
  Mixed m;
  EXPECT_EQ(voxelgi::ComputeUnreadable(m.Actor), "");
  m.Mapper->InterpolateScalarsBeforeMappingOn();
  EXPECT_EQ(voxelgi::ComputeUnreadable(m.Actor), "scalars interpolated before mapping");
  m.Mapper->InterpolateScalarsBeforeMappingOff();
  vtkNew<vtkTexture> texture;
  m.Actor->SetTexture(texture);
  EXPECT_EQ(voxelgi::ComputeUnreadable(m.Actor), "textures");
  m.Actor->SetTexture(nullptr);
  vtkNew<vtkProperty> back;
  m.Actor->SetBackfaceProperty(back);
  EXPECT_EQ(voxelgi::ComputeUnreadable(m.Actor), "a backface property");

  m.Actor->SetBackfaceProperty(nullptr);
  // A follower draws as an actor until it has a camera to turn with.
  vtkNew<vtkFollower> follower;
  follower->SetMapper(m.Mapper);
  EXPECT_EQ(voxelgi::ComputeUnreadable(follower), "");
  vtkNew<vtkCamera> camera;
  follower->SetCamera(camera);
  EXPECT_EQ(voxelgi::ComputeUnreadable(follower), "actor class vtkFollower (turning with a camera)");
}
