! The collision atlas from Fortran 2008 (docs/atlas.md): bind(C) interfaces to bounce's C API
! (include/bounce/atlas.h), then eps, the outcome and v_stick of a few pairs of radii, as a
! coagulation code would call them in its kernel.
!
!   gfortran atlas_lookup.f90 -L<libdir> -lbounce -o atlas_lookup
!   ./atlas_lookup ATLAS.h5 R1 R2 V
!
! Prints "cor sticks v_stick" for (R1, R2, V) [m, m, m/s]; exit 2 with a message when the atlas
! cannot be opened or the query is outside it (the atlas returns NaN there, never an
! extrapolation).
module bounce_atlas
  use, intrinsic :: iso_c_binding
  implicit none
  interface
    function bounce_atlas_open(path, model, error, error_size) bind(C, name="bounce_atlas_open")
      import :: c_ptr, c_char, c_size_t
      character(kind=c_char), intent(in) :: path(*), model(*)
      character(kind=c_char), intent(out) :: error(*)
      integer(c_size_t), value :: error_size
      type(c_ptr) :: bounce_atlas_open
    end function
    subroutine bounce_atlas_close(atlas) bind(C, name="bounce_atlas_close")
      import :: c_ptr
      type(c_ptr), value :: atlas
    end subroutine
    function bounce_atlas_cor(atlas, r1, r2, v) bind(C, name="bounce_atlas_cor")
      import :: c_ptr, c_double
      type(c_ptr), value :: atlas
      real(c_double), value :: r1, r2, v
      real(c_double) :: bounce_atlas_cor
    end function
    function bounce_atlas_sticks(atlas, r1, r2, v) bind(C, name="bounce_atlas_sticks")
      import :: c_ptr, c_double, c_int
      type(c_ptr), value :: atlas
      real(c_double), value :: r1, r2, v
      integer(c_int) :: bounce_atlas_sticks
    end function
    function bounce_atlas_v_stick(atlas, r1, r2) bind(C, name="bounce_atlas_v_stick")
      import :: c_ptr, c_double
      type(c_ptr), value :: atlas
      real(c_double), value :: r1, r2
      real(c_double) :: bounce_atlas_v_stick
    end function
  end interface
end module bounce_atlas

program atlas_lookup
  use, intrinsic :: iso_c_binding
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use bounce_atlas
  implicit none
  character(len=4096) :: path, word
  character(kind=c_char) :: error(512)
  type(c_ptr) :: atlas
  real(c_double) :: r1, r2, v, cor, v_stick
  integer :: sticks, i, status

  if (command_argument_count() /= 4) then
    write (0, '(a)') 'usage: atlas_lookup ATLAS.h5 R1 R2 V'
    stop 2
  end if
  call get_command_argument(1, path)
  call get_command_argument(2, word)
  read (word, *, iostat=status) r1
  if (status == 0) then
    call get_command_argument(3, word)
    read (word, *, iostat=status) r2
  end if
  if (status == 0) then
    call get_command_argument(4, word)
    read (word, *, iostat=status) v
  end if
  if (status /= 0) then
    write (0, '(a)') 'atlas_lookup: R1, R2 and V must be numbers'
    stop 2
  end if

  atlas = bounce_atlas_open(trim(path)//c_null_char, c_null_char, error, int(size(error), c_size_t))
  if (.not. c_associated(atlas)) then
    write (0, '(a)', advance='no') 'atlas_lookup: '
    do i = 1, size(error)
      if (error(i) == c_null_char) exit
      write (0, '(a)', advance='no') error(i)
    end do
    write (0, *)
    stop 2
  end if

  cor = bounce_atlas_cor(atlas, r1, r2, v)
  sticks = bounce_atlas_sticks(atlas, r1, r2, v)
  v_stick = bounce_atlas_v_stick(atlas, r1, r2)
  call bounce_atlas_close(atlas)
  if (ieee_is_nan(cor) .or. sticks < 0) then
    write (0, '(a)') 'atlas_lookup: the query is outside the atlas (its radii or speeds)'
    stop 2
  end if
  write (*, '(es24.16, 1x, i1, 1x, es24.16)') cor, sticks, v_stick
end program atlas_lookup
