

module command_parser(clock,start,address,max_width,max_height,bus$ar_valid,bus$ar_ready,bus$ar_addr,bus$ar_len,bus$ar_size,bus$ar_burst,bus$r_valid,bus$r_ready,bus$r_data,bus$r_resp,out$valid,out$ready,out$v0_x,out$v0_y,out$v0_z,out$v0_c0,out$v0_c1,out$v0_c2,out$v0_iw,out$v1_x,out$v1_y,out$v1_z,out$v1_c0,out$v1_c1,out$v1_c2,out$v1_iw,out$v2_x,out$v2_y,out$v2_z,out$v2_c0,out$v2_c1,out$v2_c2,out$v2_iw,out$end_of_buffer,out$end_of_frame,render_valid,width,height,cull_back,background,state,fault,frame_done,buffer_done);
    
    // Module arguments
    input wire  clock;
    input wire  start;
    input wire  [31:0] address;
    input wire  [15:0] max_width;
    input wire  [15:0] max_height;
    output reg  bus$ar_valid;
    input wire  bus$ar_ready;
    output reg  [31:0] bus$ar_addr;
    output reg  [7:0] bus$ar_len;
    output reg  [2:0] bus$ar_size;
    output reg  [1:0] bus$ar_burst;
    input wire  bus$r_valid;
    output reg  bus$r_ready;
    input wire  [127:0] bus$r_data;
    input wire  [1:0] bus$r_resp;
    output reg  out$valid;
    input wire  out$ready;
    output reg  [15:0] out$v0_x;
    output reg  [15:0] out$v0_y;
    output reg  [17:0] out$v0_z;
    output reg  [7:0] out$v0_c0;
    output reg  [7:0] out$v0_c1;
    output reg  [7:0] out$v0_c2;
    output reg  [15:0] out$v0_iw;
    output reg  [15:0] out$v1_x;
    output reg  [15:0] out$v1_y;
    output reg  [17:0] out$v1_z;
    output reg  [7:0] out$v1_c0;
    output reg  [7:0] out$v1_c1;
    output reg  [7:0] out$v1_c2;
    output reg  [15:0] out$v1_iw;
    output reg  [15:0] out$v2_x;
    output reg  [15:0] out$v2_y;
    output reg  [17:0] out$v2_z;
    output reg  [7:0] out$v2_c0;
    output reg  [7:0] out$v2_c1;
    output reg  [7:0] out$v2_c2;
    output reg  [15:0] out$v2_iw;
    output reg  out$end_of_buffer;
    output reg  out$end_of_frame;
    output reg  render_valid;
    output reg  [15:0] width;
    output reg  [15:0] height;
    output reg  cull_back;
    output reg  [23:0] background;
    output reg  [2:0] state;
    output reg  [3:0] fault;
    output reg  frame_done;
    output reg  buffer_done;
    
    // Constant declarations
    localparam  five = 16'h5;
    localparam  four = 16'h4;
    localparam  at_y = 16'h10;
    localparam  at_z = 16'h20;
    localparam  at_c0 = 16'h32;
    localparam  at_c1 = 16'h3a;
    localparam  at_c2 = 16'h42;
    
    // Enums
    localparam ParserState$Init = 0;
    localparam ParserState$Header = 1;
    localparam ParserState$TriIndex = 2;
    localparam ParserState$VertexFetch = 3;
    localparam ParserState$CpReady = 4;
    localparam ParserState$End = 5;
    localparam ParserState$Error = 6;
    localparam BurstKind$Header = 0;
    localparam BurstKind$Index = 1;
    localparam BurstKind$Vertex = 2;
    
    // Stub signals
    reg  [2:0] st$d;
    wire  [2:0] st$q;
    reg  st$clock;
    reg  [3:0] fault_r$d;
    wire  [3:0] fault_r$q;
    reg  fault_r$clock;
    reg  [31:0] base$d;
    wire  [31:0] base$q;
    reg  base$clock;
    reg  render_r$d;
    wire  render_r$q;
    reg  render_r$clock;
    reg  [15:0] width_r$d;
    wire  [15:0] width_r$q;
    reg  width_r$clock;
    reg  [15:0] height_r$d;
    wire  [15:0] height_r$q;
    reg  height_r$clock;
    reg  cull_r$d;
    wire  cull_r$q;
    reg  cull_r$clock;
    reg  [23:0] background_r$d;
    wire  [23:0] background_r$q;
    reg  background_r$clock;
    reg  [31:0] triangles$d;
    wire  [31:0] triangles$q;
    reg  triangles$clock;
    reg  [31:0] vertices$d;
    wire  [31:0] vertices$q;
    reg  vertices$clock;
    reg  [31:0] index_addr$d;
    wire  [31:0] index_addr$q;
    reg  index_addr$clock;
    reg  [31:0] vertex_base$d;
    wire  [31:0] vertex_base$q;
    reg  vertex_base$clock;
    reg  ar_valid$d;
    wire  ar_valid$q;
    reg  ar_valid$clock;
    reg  [31:0] ar_addr$d;
    wire  [31:0] ar_addr$q;
    reg  ar_addr$clock;
    reg  [7:0] ar_len$d;
    wire  [7:0] ar_len$q;
    reg  ar_len$clock;
    reg  burst$d;
    wire  burst$q;
    reg  burst$clock;
    reg  [1:0] kind$d;
    wire  [1:0] kind$q;
    reg  kind$clock;
    reg  [3:0] beat$d;
    wire  [3:0] beat$q;
    reg  beat$clock;
    reg  complete$d;
    wire  complete$q;
    reg  complete$clock;
    reg  bus_error$d;
    wire  bus_error$q;
    reg  bus_error$clock;
    reg  [31:0] w$0$d;
    wire  [31:0] w$0$q;
    reg  w$0$clock;
    reg  [31:0] w$1$d;
    wire  [31:0] w$1$q;
    reg  w$1$clock;
    reg  [31:0] w$2$d;
    wire  [31:0] w$2$q;
    reg  w$2$clock;
    reg  [31:0] w$3$d;
    wire  [31:0] w$3$q;
    reg  w$3$clock;
    reg  [31:0] w$4$d;
    wire  [31:0] w$4$q;
    reg  w$4$clock;
    reg  [31:0] w$5$d;
    wire  [31:0] w$5$q;
    reg  w$5$clock;
    reg  [31:0] w$6$d;
    wire  [31:0] w$6$q;
    reg  w$6$clock;
    reg  [31:0] w$7$d;
    wire  [31:0] w$7$q;
    reg  w$7$clock;
    reg  [31:0] w$8$d;
    wire  [31:0] w$8$q;
    reg  w$8$clock;
    reg  [31:0] w$9$d;
    wire  [31:0] w$9$q;
    reg  w$9$clock;
    reg  [31:0] w$10$d;
    wire  [31:0] w$10$q;
    reg  w$10$clock;
    reg  [31:0] w$11$d;
    wire  [31:0] w$11$q;
    reg  w$11$clock;
    reg  [31:0] w$12$d;
    wire  [31:0] w$12$q;
    reg  w$12$clock;
    reg  [31:0] w$13$d;
    wire  [31:0] w$13$q;
    reg  w$13$clock;
    reg  [31:0] w$14$d;
    wire  [31:0] w$14$q;
    reg  w$14$clock;
    reg  [31:0] w$15$d;
    wire  [31:0] w$15$q;
    reg  w$15$clock;
    reg  [31:0] w$16$d;
    wire  [31:0] w$16$q;
    reg  w$16$clock;
    reg  [31:0] w$17$d;
    wire  [31:0] w$17$q;
    reg  w$17$clock;
    reg  [31:0] w$18$d;
    wire  [31:0] w$18$q;
    reg  w$18$clock;
    reg  [31:0] w$19$d;
    wire  [31:0] w$19$q;
    reg  w$19$clock;
    reg  [31:0] w$20$d;
    wire  [31:0] w$20$q;
    reg  w$20$clock;
    reg  [31:0] w$21$d;
    wire  [31:0] w$21$q;
    reg  w$21$clock;
    reg  [31:0] w$22$d;
    wire  [31:0] w$22$q;
    reg  w$22$clock;
    reg  [31:0] w$23$d;
    wire  [31:0] w$23$q;
    reg  w$23$clock;
    reg  [31:0] t$d;
    wire  [31:0] t$q;
    reg  t$clock;
    reg  [31:0] rec_v$0$d;
    wire  [31:0] rec_v$0$q;
    reg  rec_v$0$clock;
    reg  [31:0] rec_v$1$d;
    wire  [31:0] rec_v$1$q;
    reg  rec_v$1$clock;
    reg  [31:0] rec_v$2$d;
    wire  [31:0] rec_v$2$q;
    reg  rec_v$2$clock;
    reg  [15:0] rec_iw$0$d;
    wire  [15:0] rec_iw$0$q;
    reg  rec_iw$0$clock;
    reg  [15:0] rec_iw$1$d;
    wire  [15:0] rec_iw$1$q;
    reg  rec_iw$1$clock;
    reg  [15:0] rec_iw$2$d;
    wire  [15:0] rec_iw$2$q;
    reg  rec_iw$2$clock;
    reg  rec_eob$d;
    wire  rec_eob$q;
    reg  rec_eob$clock;
    reg  rec_eof$d;
    wire  rec_eof$q;
    reg  rec_eof$clock;
    reg  ahead_valid$d;
    wire  ahead_valid$q;
    reg  ahead_valid$clock;
    reg  [3:0] ahead_fault$d;
    wire  [3:0] ahead_fault$q;
    reg  ahead_fault$clock;
    reg  [31:0] ahead_v$0$d;
    wire  [31:0] ahead_v$0$q;
    reg  ahead_v$0$clock;
    reg  [31:0] ahead_v$1$d;
    wire  [31:0] ahead_v$1$q;
    reg  ahead_v$1$clock;
    reg  [31:0] ahead_v$2$d;
    wire  [31:0] ahead_v$2$q;
    reg  ahead_v$2$clock;
    reg  [15:0] ahead_iw$0$d;
    wire  [15:0] ahead_iw$0$q;
    reg  ahead_iw$0$clock;
    reg  [15:0] ahead_iw$1$d;
    wire  [15:0] ahead_iw$1$q;
    reg  ahead_iw$1$clock;
    reg  [15:0] ahead_iw$2$d;
    wire  [15:0] ahead_iw$2$q;
    reg  ahead_iw$2$clock;
    reg  ahead_eob$d;
    wire  ahead_eob$q;
    reg  ahead_eob$clock;
    reg  ahead_eof$d;
    wire  ahead_eof$q;
    reg  ahead_eof$clock;
    reg  [1:0] k$d;
    wire  [1:0] k$q;
    reg  k$clock;
    reg  [73:0] asm$0$d;
    wire  [73:0] asm$0$q;
    reg  asm$0$clock;
    reg  [73:0] asm$1$d;
    wire  [73:0] asm$1$q;
    reg  asm$1$clock;
    reg  [73:0] asm$2$d;
    wire  [73:0] asm$2$q;
    reg  asm$2$clock;
    reg  [15:0] valid$0$d;
    wire  [15:0] valid$0$q;
    reg  valid$0$clock;
    reg  [15:0] valid$1$d;
    wire  [15:0] valid$1$q;
    reg  valid$1$clock;
    reg  [15:0] valid$2$d;
    wire  [15:0] valid$2$q;
    reg  valid$2$clock;
    reg  [15:0] valid$3$d;
    wire  [15:0] valid$3$q;
    reg  valid$3$clock;
    reg  [15:0] valid$4$d;
    wire  [15:0] valid$4$q;
    reg  valid$4$clock;
    reg  [15:0] valid$5$d;
    wire  [15:0] valid$5$q;
    reg  valid$5$clock;
    reg  [15:0] valid$6$d;
    wire  [15:0] valid$6$q;
    reg  valid$6$clock;
    reg  [15:0] valid$7$d;
    wire  [15:0] valid$7$q;
    reg  valid$7$clock;
    reg  [15:0] valid$8$d;
    wire  [15:0] valid$8$q;
    reg  valid$8$clock;
    reg  [15:0] valid$9$d;
    wire  [15:0] valid$9$q;
    reg  valid$9$clock;
    reg  [15:0] valid$10$d;
    wire  [15:0] valid$10$q;
    reg  valid$10$clock;
    reg  [15:0] valid$11$d;
    wire  [15:0] valid$11$q;
    reg  valid$11$clock;
    reg  [15:0] valid$12$d;
    wire  [15:0] valid$12$q;
    reg  valid$12$clock;
    reg  [15:0] valid$13$d;
    wire  [15:0] valid$13$q;
    reg  valid$13$clock;
    reg  [15:0] valid$14$d;
    wire  [15:0] valid$14$q;
    reg  valid$14$clock;
    reg  [15:0] valid$15$d;
    wire  [15:0] valid$15$q;
    reg  valid$15$clock;
    reg  [15:0] valid$16$d;
    wire  [15:0] valid$16$q;
    reg  valid$16$clock;
    reg  [15:0] valid$17$d;
    wire  [15:0] valid$17$q;
    reg  valid$17$clock;
    reg  [15:0] valid$18$d;
    wire  [15:0] valid$18$q;
    reg  valid$18$clock;
    reg  [15:0] valid$19$d;
    wire  [15:0] valid$19$q;
    reg  valid$19$clock;
    reg  [15:0] valid$20$d;
    wire  [15:0] valid$20$q;
    reg  valid$20$clock;
    reg  [15:0] valid$21$d;
    wire  [15:0] valid$21$q;
    reg  valid$21$clock;
    reg  [15:0] valid$22$d;
    wire  [15:0] valid$22$q;
    reg  valid$22$clock;
    reg  [15:0] valid$23$d;
    wire  [15:0] valid$23$q;
    reg  valid$23$clock;
    reg  [15:0] valid$24$d;
    wire  [15:0] valid$24$q;
    reg  valid$24$clock;
    reg  [15:0] valid$25$d;
    wire  [15:0] valid$25$q;
    reg  valid$25$clock;
    reg  [15:0] valid$26$d;
    wire  [15:0] valid$26$q;
    reg  valid$26$clock;
    reg  [15:0] valid$27$d;
    wire  [15:0] valid$27$q;
    reg  valid$27$clock;
    reg  [15:0] valid$28$d;
    wire  [15:0] valid$28$q;
    reg  valid$28$clock;
    reg  [15:0] valid$29$d;
    wire  [15:0] valid$29$q;
    reg  valid$29$clock;
    reg  [15:0] valid$30$d;
    wire  [15:0] valid$30$q;
    reg  valid$30$clock;
    reg  [15:0] valid$31$d;
    wire  [15:0] valid$31$q;
    reg  valid$31$clock;
    reg  [8:0] tag_ram$read_address;
    reg  tag_ram$read_clock;
    wire  [31:0] tag_ram$read_data;
    reg  [8:0] tag_ram$write_address;
    reg  tag_ram$write_clock;
    reg  [31:0] tag_ram$write_data;
    reg  tag_ram$write_enable;
    reg  [8:0] vtx_ram$read_address;
    reg  vtx_ram$read_clock;
    wire  [73:0] vtx_ram$read_data;
    reg  [8:0] vtx_ram$write_address;
    reg  vtx_ram$write_clock;
    reg  [73:0] vtx_ram$write_data;
    reg  vtx_ram$write_enable;
    reg  byp_valid$d;
    wire  byp_valid$q;
    reg  byp_valid$clock;
    reg  [31:0] byp_tag$d;
    wire  [31:0] byp_tag$q;
    reg  byp_tag$clock;
    reg  [73:0] byp_vtx$d;
    wire  [73:0] byp_vtx$q;
    reg  byp_vtx$clock;
    reg  out_valid$d;
    wire  out_valid$q;
    reg  out_valid$clock;
    reg  [73:0] out_vtx$0$d;
    wire  [73:0] out_vtx$0$q;
    reg  out_vtx$0$clock;
    reg  [73:0] out_vtx$1$d;
    wire  [73:0] out_vtx$1$q;
    reg  out_vtx$1$clock;
    reg  [73:0] out_vtx$2$d;
    wire  [73:0] out_vtx$2$q;
    reg  out_vtx$2$clock;
    reg  [15:0] out_iw$0$d;
    wire  [15:0] out_iw$0$q;
    reg  out_iw$0$clock;
    reg  [15:0] out_iw$1$d;
    wire  [15:0] out_iw$1$q;
    reg  out_iw$1$clock;
    reg  [15:0] out_iw$2$d;
    wire  [15:0] out_iw$2$q;
    reg  out_iw$2$clock;
    reg  out_eob$d;
    wire  out_eob$q;
    reg  out_eob$clock;
    reg  out_eof$d;
    wire  out_eof$q;
    reg  out_eof$clock;
    reg  frame_r$d;
    wire  frame_r$q;
    reg  frame_r$clock;
    reg  buffer_r$d;
    wire  buffer_r$q;
    reg  buffer_r$clock;
    reg  [31:0] header_check$h$0;
    reg  [31:0] header_check$h$1;
    reg  [31:0] header_check$h$2;
    reg  [31:0] header_check$h$3;
    reg  [31:0] header_check$h$4;
    reg  [31:0] header_check$h$5;
    reg  [31:0] header_check$h$6;
    reg  [31:0] header_check$h$7;
    reg  [31:0] header_check$h$8;
    reg  [31:0] header_check$h$9;
    reg  [31:0] header_check$h$10;
    reg  [31:0] header_check$h$11;
    reg  [31:0] header_check$h$12;
    reg  [31:0] header_check$h$13;
    reg  [31:0] header_check$h$14;
    reg  [31:0] header_check$h$15;
    reg  [31:0] header_check$h$16;
    reg  [31:0] header_check$h$17;
    reg  [31:0] header_check$h$18;
    reg  [31:0] header_check$h$19;
    reg  [31:0] header_check$h$20;
    reg  [31:0] header_check$h$21;
    reg  [31:0] header_check$h$22;
    reg  [31:0] header_check$h$23;
    reg  [31:0] header_check$base;
    reg  [15:0] header_check$max_width;
    reg  [15:0] header_check$max_height;
    wire  [3:0] header_check$fault;
    reg  [31:0] index_check$r$0;
    reg  [31:0] index_check$r$1;
    reg  [31:0] index_check$r$2;
    reg  [31:0] index_check$r$3;
    reg  [31:0] index_check$r$4;
    reg  [31:0] index_check$r$5;
    reg  [31:0] index_check$r$6;
    reg  [31:0] index_check$r$7;
    reg  [31:0] index_check$t;
    reg  [31:0] index_check$triangles;
    reg  [31:0] index_check$vertices;
    wire  [3:0] index_check$fault;
    reg  [31:0] vertex_check$r$0;
    reg  [31:0] vertex_check$r$1;
    reg  [31:0] vertex_check$r$2;
    reg  [31:0] vertex_check$r$3;
    reg  [31:0] vertex_check$r$4;
    reg  [31:0] vertex_check$r$5;
    reg  [31:0] vertex_check$r$6;
    reg  [31:0] vertex_check$r$7;
    wire  [3:0] vertex_check$fault;
    
    // Local signals
    reg  out_free;
    reg  beat_in;
    reg  [3:0] last_beat;
    reg  go;
    reg  check;
    reg  look;
    reg  hand;
    reg  vertex_in;
    reg  load_rec;
    reg  is_ahead;
    reg  load_ahead;
    reg  ask;
    reg  [31:0] ask_addr;
    reg  [1:0] ask_kind;
    reg  [1:0] kn;
    reg  [31:0] v_cur;
    reg  [8:0] slot;
    reg  [8:0] group;
    reg  [3:0] lane;
    reg  held;
    reg  [31:0] tag;
    reg  [73:0] vtx;
    reg  hit;
    reg  [73:0] fetched;
    reg  [73:0] cur;
    reg  [8:0] rvn$0;
    reg  [8:0] rvn$1;
    reg  [8:0] rvn$2;
    reg  [8:0] v_next;
    
    // Sub module instances
    command_parser$st st(
        .d(st$d),
        .q(st$q),
        .clock(st$clock)
    );
    command_parser$fault_r fault_r(
        .d(fault_r$d),
        .q(fault_r$q),
        .clock(fault_r$clock)
    );
    command_parser$base base(
        .d(base$d),
        .q(base$q),
        .clock(base$clock)
    );
    command_parser$render_r render_r(
        .d(render_r$d),
        .q(render_r$q),
        .clock(render_r$clock)
    );
    command_parser$width_r width_r(
        .d(width_r$d),
        .q(width_r$q),
        .clock(width_r$clock)
    );
    command_parser$height_r height_r(
        .d(height_r$d),
        .q(height_r$q),
        .clock(height_r$clock)
    );
    command_parser$cull_r cull_r(
        .d(cull_r$d),
        .q(cull_r$q),
        .clock(cull_r$clock)
    );
    command_parser$background_r background_r(
        .d(background_r$d),
        .q(background_r$q),
        .clock(background_r$clock)
    );
    command_parser$triangles triangles(
        .d(triangles$d),
        .q(triangles$q),
        .clock(triangles$clock)
    );
    command_parser$vertices vertices(
        .d(vertices$d),
        .q(vertices$q),
        .clock(vertices$clock)
    );
    command_parser$index_addr index_addr(
        .d(index_addr$d),
        .q(index_addr$q),
        .clock(index_addr$clock)
    );
    command_parser$vertex_base vertex_base(
        .d(vertex_base$d),
        .q(vertex_base$q),
        .clock(vertex_base$clock)
    );
    command_parser$ar_valid ar_valid(
        .d(ar_valid$d),
        .q(ar_valid$q),
        .clock(ar_valid$clock)
    );
    command_parser$ar_addr ar_addr(
        .d(ar_addr$d),
        .q(ar_addr$q),
        .clock(ar_addr$clock)
    );
    command_parser$ar_len ar_len(
        .d(ar_len$d),
        .q(ar_len$q),
        .clock(ar_len$clock)
    );
    command_parser$burst burst(
        .d(burst$d),
        .q(burst$q),
        .clock(burst$clock)
    );
    command_parser$kind kind(
        .d(kind$d),
        .q(kind$q),
        .clock(kind$clock)
    );
    command_parser$beat beat(
        .d(beat$d),
        .q(beat$q),
        .clock(beat$clock)
    );
    command_parser$complete complete(
        .d(complete$d),
        .q(complete$q),
        .clock(complete$clock)
    );
    command_parser$bus_error bus_error(
        .d(bus_error$d),
        .q(bus_error$q),
        .clock(bus_error$clock)
    );
    command_parser$w$0 w$0(
        .d(w$0$d),
        .q(w$0$q),
        .clock(w$0$clock)
    );
    command_parser$w$1 w$1(
        .d(w$1$d),
        .q(w$1$q),
        .clock(w$1$clock)
    );
    command_parser$w$2 w$2(
        .d(w$2$d),
        .q(w$2$q),
        .clock(w$2$clock)
    );
    command_parser$w$3 w$3(
        .d(w$3$d),
        .q(w$3$q),
        .clock(w$3$clock)
    );
    command_parser$w$4 w$4(
        .d(w$4$d),
        .q(w$4$q),
        .clock(w$4$clock)
    );
    command_parser$w$5 w$5(
        .d(w$5$d),
        .q(w$5$q),
        .clock(w$5$clock)
    );
    command_parser$w$6 w$6(
        .d(w$6$d),
        .q(w$6$q),
        .clock(w$6$clock)
    );
    command_parser$w$7 w$7(
        .d(w$7$d),
        .q(w$7$q),
        .clock(w$7$clock)
    );
    command_parser$w$8 w$8(
        .d(w$8$d),
        .q(w$8$q),
        .clock(w$8$clock)
    );
    command_parser$w$9 w$9(
        .d(w$9$d),
        .q(w$9$q),
        .clock(w$9$clock)
    );
    command_parser$w$10 w$10(
        .d(w$10$d),
        .q(w$10$q),
        .clock(w$10$clock)
    );
    command_parser$w$11 w$11(
        .d(w$11$d),
        .q(w$11$q),
        .clock(w$11$clock)
    );
    command_parser$w$12 w$12(
        .d(w$12$d),
        .q(w$12$q),
        .clock(w$12$clock)
    );
    command_parser$w$13 w$13(
        .d(w$13$d),
        .q(w$13$q),
        .clock(w$13$clock)
    );
    command_parser$w$14 w$14(
        .d(w$14$d),
        .q(w$14$q),
        .clock(w$14$clock)
    );
    command_parser$w$15 w$15(
        .d(w$15$d),
        .q(w$15$q),
        .clock(w$15$clock)
    );
    command_parser$w$16 w$16(
        .d(w$16$d),
        .q(w$16$q),
        .clock(w$16$clock)
    );
    command_parser$w$17 w$17(
        .d(w$17$d),
        .q(w$17$q),
        .clock(w$17$clock)
    );
    command_parser$w$18 w$18(
        .d(w$18$d),
        .q(w$18$q),
        .clock(w$18$clock)
    );
    command_parser$w$19 w$19(
        .d(w$19$d),
        .q(w$19$q),
        .clock(w$19$clock)
    );
    command_parser$w$20 w$20(
        .d(w$20$d),
        .q(w$20$q),
        .clock(w$20$clock)
    );
    command_parser$w$21 w$21(
        .d(w$21$d),
        .q(w$21$q),
        .clock(w$21$clock)
    );
    command_parser$w$22 w$22(
        .d(w$22$d),
        .q(w$22$q),
        .clock(w$22$clock)
    );
    command_parser$w$23 w$23(
        .d(w$23$d),
        .q(w$23$q),
        .clock(w$23$clock)
    );
    command_parser$t t(
        .d(t$d),
        .q(t$q),
        .clock(t$clock)
    );
    command_parser$rec_v$0 rec_v$0(
        .d(rec_v$0$d),
        .q(rec_v$0$q),
        .clock(rec_v$0$clock)
    );
    command_parser$rec_v$1 rec_v$1(
        .d(rec_v$1$d),
        .q(rec_v$1$q),
        .clock(rec_v$1$clock)
    );
    command_parser$rec_v$2 rec_v$2(
        .d(rec_v$2$d),
        .q(rec_v$2$q),
        .clock(rec_v$2$clock)
    );
    command_parser$rec_iw$0 rec_iw$0(
        .d(rec_iw$0$d),
        .q(rec_iw$0$q),
        .clock(rec_iw$0$clock)
    );
    command_parser$rec_iw$1 rec_iw$1(
        .d(rec_iw$1$d),
        .q(rec_iw$1$q),
        .clock(rec_iw$1$clock)
    );
    command_parser$rec_iw$2 rec_iw$2(
        .d(rec_iw$2$d),
        .q(rec_iw$2$q),
        .clock(rec_iw$2$clock)
    );
    command_parser$rec_eob rec_eob(
        .d(rec_eob$d),
        .q(rec_eob$q),
        .clock(rec_eob$clock)
    );
    command_parser$rec_eof rec_eof(
        .d(rec_eof$d),
        .q(rec_eof$q),
        .clock(rec_eof$clock)
    );
    command_parser$ahead_valid ahead_valid(
        .d(ahead_valid$d),
        .q(ahead_valid$q),
        .clock(ahead_valid$clock)
    );
    command_parser$ahead_fault ahead_fault(
        .d(ahead_fault$d),
        .q(ahead_fault$q),
        .clock(ahead_fault$clock)
    );
    command_parser$ahead_v$0 ahead_v$0(
        .d(ahead_v$0$d),
        .q(ahead_v$0$q),
        .clock(ahead_v$0$clock)
    );
    command_parser$ahead_v$1 ahead_v$1(
        .d(ahead_v$1$d),
        .q(ahead_v$1$q),
        .clock(ahead_v$1$clock)
    );
    command_parser$ahead_v$2 ahead_v$2(
        .d(ahead_v$2$d),
        .q(ahead_v$2$q),
        .clock(ahead_v$2$clock)
    );
    command_parser$ahead_iw$0 ahead_iw$0(
        .d(ahead_iw$0$d),
        .q(ahead_iw$0$q),
        .clock(ahead_iw$0$clock)
    );
    command_parser$ahead_iw$1 ahead_iw$1(
        .d(ahead_iw$1$d),
        .q(ahead_iw$1$q),
        .clock(ahead_iw$1$clock)
    );
    command_parser$ahead_iw$2 ahead_iw$2(
        .d(ahead_iw$2$d),
        .q(ahead_iw$2$q),
        .clock(ahead_iw$2$clock)
    );
    command_parser$ahead_eob ahead_eob(
        .d(ahead_eob$d),
        .q(ahead_eob$q),
        .clock(ahead_eob$clock)
    );
    command_parser$ahead_eof ahead_eof(
        .d(ahead_eof$d),
        .q(ahead_eof$q),
        .clock(ahead_eof$clock)
    );
    command_parser$k k(
        .d(k$d),
        .q(k$q),
        .clock(k$clock)
    );
    command_parser$asm$0 asm$0(
        .d(asm$0$d),
        .q(asm$0$q),
        .clock(asm$0$clock)
    );
    command_parser$asm$1 asm$1(
        .d(asm$1$d),
        .q(asm$1$q),
        .clock(asm$1$clock)
    );
    command_parser$asm$2 asm$2(
        .d(asm$2$d),
        .q(asm$2$q),
        .clock(asm$2$clock)
    );
    command_parser$valid$0 valid$0(
        .d(valid$0$d),
        .q(valid$0$q),
        .clock(valid$0$clock)
    );
    command_parser$valid$1 valid$1(
        .d(valid$1$d),
        .q(valid$1$q),
        .clock(valid$1$clock)
    );
    command_parser$valid$2 valid$2(
        .d(valid$2$d),
        .q(valid$2$q),
        .clock(valid$2$clock)
    );
    command_parser$valid$3 valid$3(
        .d(valid$3$d),
        .q(valid$3$q),
        .clock(valid$3$clock)
    );
    command_parser$valid$4 valid$4(
        .d(valid$4$d),
        .q(valid$4$q),
        .clock(valid$4$clock)
    );
    command_parser$valid$5 valid$5(
        .d(valid$5$d),
        .q(valid$5$q),
        .clock(valid$5$clock)
    );
    command_parser$valid$6 valid$6(
        .d(valid$6$d),
        .q(valid$6$q),
        .clock(valid$6$clock)
    );
    command_parser$valid$7 valid$7(
        .d(valid$7$d),
        .q(valid$7$q),
        .clock(valid$7$clock)
    );
    command_parser$valid$8 valid$8(
        .d(valid$8$d),
        .q(valid$8$q),
        .clock(valid$8$clock)
    );
    command_parser$valid$9 valid$9(
        .d(valid$9$d),
        .q(valid$9$q),
        .clock(valid$9$clock)
    );
    command_parser$valid$10 valid$10(
        .d(valid$10$d),
        .q(valid$10$q),
        .clock(valid$10$clock)
    );
    command_parser$valid$11 valid$11(
        .d(valid$11$d),
        .q(valid$11$q),
        .clock(valid$11$clock)
    );
    command_parser$valid$12 valid$12(
        .d(valid$12$d),
        .q(valid$12$q),
        .clock(valid$12$clock)
    );
    command_parser$valid$13 valid$13(
        .d(valid$13$d),
        .q(valid$13$q),
        .clock(valid$13$clock)
    );
    command_parser$valid$14 valid$14(
        .d(valid$14$d),
        .q(valid$14$q),
        .clock(valid$14$clock)
    );
    command_parser$valid$15 valid$15(
        .d(valid$15$d),
        .q(valid$15$q),
        .clock(valid$15$clock)
    );
    command_parser$valid$16 valid$16(
        .d(valid$16$d),
        .q(valid$16$q),
        .clock(valid$16$clock)
    );
    command_parser$valid$17 valid$17(
        .d(valid$17$d),
        .q(valid$17$q),
        .clock(valid$17$clock)
    );
    command_parser$valid$18 valid$18(
        .d(valid$18$d),
        .q(valid$18$q),
        .clock(valid$18$clock)
    );
    command_parser$valid$19 valid$19(
        .d(valid$19$d),
        .q(valid$19$q),
        .clock(valid$19$clock)
    );
    command_parser$valid$20 valid$20(
        .d(valid$20$d),
        .q(valid$20$q),
        .clock(valid$20$clock)
    );
    command_parser$valid$21 valid$21(
        .d(valid$21$d),
        .q(valid$21$q),
        .clock(valid$21$clock)
    );
    command_parser$valid$22 valid$22(
        .d(valid$22$d),
        .q(valid$22$q),
        .clock(valid$22$clock)
    );
    command_parser$valid$23 valid$23(
        .d(valid$23$d),
        .q(valid$23$q),
        .clock(valid$23$clock)
    );
    command_parser$valid$24 valid$24(
        .d(valid$24$d),
        .q(valid$24$q),
        .clock(valid$24$clock)
    );
    command_parser$valid$25 valid$25(
        .d(valid$25$d),
        .q(valid$25$q),
        .clock(valid$25$clock)
    );
    command_parser$valid$26 valid$26(
        .d(valid$26$d),
        .q(valid$26$q),
        .clock(valid$26$clock)
    );
    command_parser$valid$27 valid$27(
        .d(valid$27$d),
        .q(valid$27$q),
        .clock(valid$27$clock)
    );
    command_parser$valid$28 valid$28(
        .d(valid$28$d),
        .q(valid$28$q),
        .clock(valid$28$clock)
    );
    command_parser$valid$29 valid$29(
        .d(valid$29$d),
        .q(valid$29$q),
        .clock(valid$29$clock)
    );
    command_parser$valid$30 valid$30(
        .d(valid$30$d),
        .q(valid$30$q),
        .clock(valid$30$clock)
    );
    command_parser$valid$31 valid$31(
        .d(valid$31$d),
        .q(valid$31$q),
        .clock(valid$31$clock)
    );
    command_parser$tag_ram tag_ram(
        .read_address(tag_ram$read_address),
        .read_clock(tag_ram$read_clock),
        .read_data(tag_ram$read_data),
        .write_address(tag_ram$write_address),
        .write_clock(tag_ram$write_clock),
        .write_data(tag_ram$write_data),
        .write_enable(tag_ram$write_enable)
    );
    command_parser$vtx_ram vtx_ram(
        .read_address(vtx_ram$read_address),
        .read_clock(vtx_ram$read_clock),
        .read_data(vtx_ram$read_data),
        .write_address(vtx_ram$write_address),
        .write_clock(vtx_ram$write_clock),
        .write_data(vtx_ram$write_data),
        .write_enable(vtx_ram$write_enable)
    );
    command_parser$byp_valid byp_valid(
        .d(byp_valid$d),
        .q(byp_valid$q),
        .clock(byp_valid$clock)
    );
    command_parser$byp_tag byp_tag(
        .d(byp_tag$d),
        .q(byp_tag$q),
        .clock(byp_tag$clock)
    );
    command_parser$byp_vtx byp_vtx(
        .d(byp_vtx$d),
        .q(byp_vtx$q),
        .clock(byp_vtx$clock)
    );
    command_parser$out_valid out_valid(
        .d(out_valid$d),
        .q(out_valid$q),
        .clock(out_valid$clock)
    );
    command_parser$out_vtx$0 out_vtx$0(
        .d(out_vtx$0$d),
        .q(out_vtx$0$q),
        .clock(out_vtx$0$clock)
    );
    command_parser$out_vtx$1 out_vtx$1(
        .d(out_vtx$1$d),
        .q(out_vtx$1$q),
        .clock(out_vtx$1$clock)
    );
    command_parser$out_vtx$2 out_vtx$2(
        .d(out_vtx$2$d),
        .q(out_vtx$2$q),
        .clock(out_vtx$2$clock)
    );
    command_parser$out_iw$0 out_iw$0(
        .d(out_iw$0$d),
        .q(out_iw$0$q),
        .clock(out_iw$0$clock)
    );
    command_parser$out_iw$1 out_iw$1(
        .d(out_iw$1$d),
        .q(out_iw$1$q),
        .clock(out_iw$1$clock)
    );
    command_parser$out_iw$2 out_iw$2(
        .d(out_iw$2$d),
        .q(out_iw$2$q),
        .clock(out_iw$2$clock)
    );
    command_parser$out_eob out_eob(
        .d(out_eob$d),
        .q(out_eob$q),
        .clock(out_eob$clock)
    );
    command_parser$out_eof out_eof(
        .d(out_eof$d),
        .q(out_eof$q),
        .clock(out_eof$clock)
    );
    command_parser$frame_r frame_r(
        .d(frame_r$d),
        .q(frame_r$q),
        .clock(frame_r$clock)
    );
    command_parser$buffer_r buffer_r(
        .d(buffer_r$d),
        .q(buffer_r$q),
        .clock(buffer_r$clock)
    );
    command_parser$header_check header_check(
        .h$0(header_check$h$0),
        .h$1(header_check$h$1),
        .h$2(header_check$h$2),
        .h$3(header_check$h$3),
        .h$4(header_check$h$4),
        .h$5(header_check$h$5),
        .h$6(header_check$h$6),
        .h$7(header_check$h$7),
        .h$8(header_check$h$8),
        .h$9(header_check$h$9),
        .h$10(header_check$h$10),
        .h$11(header_check$h$11),
        .h$12(header_check$h$12),
        .h$13(header_check$h$13),
        .h$14(header_check$h$14),
        .h$15(header_check$h$15),
        .h$16(header_check$h$16),
        .h$17(header_check$h$17),
        .h$18(header_check$h$18),
        .h$19(header_check$h$19),
        .h$20(header_check$h$20),
        .h$21(header_check$h$21),
        .h$22(header_check$h$22),
        .h$23(header_check$h$23),
        .base(header_check$base),
        .max_width(header_check$max_width),
        .max_height(header_check$max_height),
        .fault(header_check$fault)
    );
    command_parser$index_check index_check(
        .r$0(index_check$r$0),
        .r$1(index_check$r$1),
        .r$2(index_check$r$2),
        .r$3(index_check$r$3),
        .r$4(index_check$r$4),
        .r$5(index_check$r$5),
        .r$6(index_check$r$6),
        .r$7(index_check$r$7),
        .t(index_check$t),
        .triangles(index_check$triangles),
        .vertices(index_check$vertices),
        .fault(index_check$fault)
    );
    command_parser$vertex_check vertex_check(
        .r$0(vertex_check$r$0),
        .r$1(vertex_check$r$1),
        .r$2(vertex_check$r$2),
        .r$3(vertex_check$r$3),
        .r$4(vertex_check$r$4),
        .r$5(vertex_check$r$5),
        .r$6(vertex_check$r$6),
        .r$7(vertex_check$r$7),
        .fault(vertex_check$fault)
    );
    
    // Update code
    always @(*) begin
        st$clock = clock;
        fault_r$clock = clock;
        base$clock = clock;
        render_r$clock = clock;
        width_r$clock = clock;
        height_r$clock = clock;
        cull_r$clock = clock;
        background_r$clock = clock;
        triangles$clock = clock;
        vertices$clock = clock;
        index_addr$clock = clock;
        vertex_base$clock = clock;
        ar_valid$clock = clock;
        ar_addr$clock = clock;
        ar_len$clock = clock;
        burst$clock = clock;
        kind$clock = clock;
        beat$clock = clock;
        complete$clock = clock;
        bus_error$clock = clock;
        t$clock = clock;
        rec_eob$clock = clock;
        rec_eof$clock = clock;
        ahead_valid$clock = clock;
        ahead_fault$clock = clock;
        ahead_eob$clock = clock;
        ahead_eof$clock = clock;
        k$clock = clock;
        byp_valid$clock = clock;
        byp_tag$clock = clock;
        byp_vtx$clock = clock;
        out_valid$clock = clock;
        out_eob$clock = clock;
        out_eof$clock = clock;
        frame_r$clock = clock;
        buffer_r$clock = clock;
        st$d = st$q;
        fault_r$d = fault_r$q;
        base$d = base$q;
        render_r$d = render_r$q;
        width_r$d = width_r$q;
        height_r$d = height_r$q;
        cull_r$d = cull_r$q;
        background_r$d = background_r$q;
        triangles$d = triangles$q;
        vertices$d = vertices$q;
        index_addr$d = index_addr$q;
        vertex_base$d = vertex_base$q;
        ar_valid$d = ar_valid$q;
        ar_addr$d = ar_addr$q;
        ar_len$d = ar_len$q;
        burst$d = burst$q;
        kind$d = kind$q;
        beat$d = beat$q;
        complete$d = complete$q;
        bus_error$d = bus_error$q;
        t$d = t$q;
        rec_eob$d = rec_eob$q;
        rec_eof$d = rec_eof$q;
        ahead_valid$d = ahead_valid$q;
        ahead_fault$d = ahead_fault$q;
        ahead_eob$d = ahead_eob$q;
        ahead_eof$d = ahead_eof$q;
        k$d = k$q;
        byp_valid$d = byp_valid$q;
        byp_tag$d = byp_tag$q;
        byp_vtx$d = byp_vtx$q;
        out_valid$d = out_valid$q;
        out_eob$d = out_eob$q;
        out_eof$d = out_eof$q;
        frame_r$d = frame_r$q;
        buffer_r$d = buffer_r$q;
        rec_v$0$clock = clock;
        rec_v$0$d = rec_v$0$q;
        rec_iw$0$clock = clock;
        rec_iw$0$d = rec_iw$0$q;
        ahead_v$0$clock = clock;
        ahead_v$0$d = ahead_v$0$q;
        ahead_iw$0$clock = clock;
        ahead_iw$0$d = ahead_iw$0$q;
        asm$0$clock = clock;
        asm$0$d = asm$0$q;
        out_vtx$0$clock = clock;
        out_vtx$0$d = out_vtx$0$q;
        out_iw$0$clock = clock;
        out_iw$0$d = out_iw$0$q;
        rec_v$1$clock = clock;
        rec_v$1$d = rec_v$1$q;
        rec_iw$1$clock = clock;
        rec_iw$1$d = rec_iw$1$q;
        ahead_v$1$clock = clock;
        ahead_v$1$d = ahead_v$1$q;
        ahead_iw$1$clock = clock;
        ahead_iw$1$d = ahead_iw$1$q;
        asm$1$clock = clock;
        asm$1$d = asm$1$q;
        out_vtx$1$clock = clock;
        out_vtx$1$d = out_vtx$1$q;
        out_iw$1$clock = clock;
        out_iw$1$d = out_iw$1$q;
        rec_v$2$clock = clock;
        rec_v$2$d = rec_v$2$q;
        rec_iw$2$clock = clock;
        rec_iw$2$d = rec_iw$2$q;
        ahead_v$2$clock = clock;
        ahead_v$2$d = ahead_v$2$q;
        ahead_iw$2$clock = clock;
        ahead_iw$2$d = ahead_iw$2$q;
        asm$2$clock = clock;
        asm$2$d = asm$2$q;
        out_vtx$2$clock = clock;
        out_vtx$2$d = out_vtx$2$q;
        out_iw$2$clock = clock;
        out_iw$2$d = out_iw$2$q;
        w$0$clock = clock;
        w$0$d = w$0$q;
        w$1$clock = clock;
        w$1$d = w$1$q;
        w$2$clock = clock;
        w$2$d = w$2$q;
        w$3$clock = clock;
        w$3$d = w$3$q;
        w$4$clock = clock;
        w$4$d = w$4$q;
        w$5$clock = clock;
        w$5$d = w$5$q;
        w$6$clock = clock;
        w$6$d = w$6$q;
        w$7$clock = clock;
        w$7$d = w$7$q;
        w$8$clock = clock;
        w$8$d = w$8$q;
        w$9$clock = clock;
        w$9$d = w$9$q;
        w$10$clock = clock;
        w$10$d = w$10$q;
        w$11$clock = clock;
        w$11$d = w$11$q;
        w$12$clock = clock;
        w$12$d = w$12$q;
        w$13$clock = clock;
        w$13$d = w$13$q;
        w$14$clock = clock;
        w$14$d = w$14$q;
        w$15$clock = clock;
        w$15$d = w$15$q;
        w$16$clock = clock;
        w$16$d = w$16$q;
        w$17$clock = clock;
        w$17$d = w$17$q;
        w$18$clock = clock;
        w$18$d = w$18$q;
        w$19$clock = clock;
        w$19$d = w$19$q;
        w$20$clock = clock;
        w$20$d = w$20$q;
        w$21$clock = clock;
        w$21$d = w$21$q;
        w$22$clock = clock;
        w$22$d = w$22$q;
        w$23$clock = clock;
        w$23$d = w$23$q;
        valid$0$clock = clock;
        valid$0$d = valid$0$q;
        valid$1$clock = clock;
        valid$1$d = valid$1$q;
        valid$2$clock = clock;
        valid$2$d = valid$2$q;
        valid$3$clock = clock;
        valid$3$d = valid$3$q;
        valid$4$clock = clock;
        valid$4$d = valid$4$q;
        valid$5$clock = clock;
        valid$5$d = valid$5$q;
        valid$6$clock = clock;
        valid$6$d = valid$6$q;
        valid$7$clock = clock;
        valid$7$d = valid$7$q;
        valid$8$clock = clock;
        valid$8$d = valid$8$q;
        valid$9$clock = clock;
        valid$9$d = valid$9$q;
        valid$10$clock = clock;
        valid$10$d = valid$10$q;
        valid$11$clock = clock;
        valid$11$d = valid$11$q;
        valid$12$clock = clock;
        valid$12$d = valid$12$q;
        valid$13$clock = clock;
        valid$13$d = valid$13$q;
        valid$14$clock = clock;
        valid$14$d = valid$14$q;
        valid$15$clock = clock;
        valid$15$d = valid$15$q;
        valid$16$clock = clock;
        valid$16$d = valid$16$q;
        valid$17$clock = clock;
        valid$17$d = valid$17$q;
        valid$18$clock = clock;
        valid$18$d = valid$18$q;
        valid$19$clock = clock;
        valid$19$d = valid$19$q;
        valid$20$clock = clock;
        valid$20$d = valid$20$q;
        valid$21$clock = clock;
        valid$21$d = valid$21$q;
        valid$22$clock = clock;
        valid$22$d = valid$22$q;
        valid$23$clock = clock;
        valid$23$d = valid$23$q;
        valid$24$clock = clock;
        valid$24$d = valid$24$q;
        valid$25$clock = clock;
        valid$25$d = valid$25$q;
        valid$26$clock = clock;
        valid$26$d = valid$26$q;
        valid$27$clock = clock;
        valid$27$d = valid$27$q;
        valid$28$clock = clock;
        valid$28$d = valid$28$q;
        valid$29$clock = clock;
        valid$29$d = valid$29$q;
        valid$30$clock = clock;
        valid$30$d = valid$30$q;
        valid$31$clock = clock;
        valid$31$d = valid$31$q;
        tag_ram$read_clock = clock;
        tag_ram$write_clock = clock;
        vtx_ram$read_clock = clock;
        vtx_ram$write_clock = clock;
        kn = k$q;
        load_rec = 1'b0;
        load_ahead = 1'b0;
        ask = 1'b0;
        ask_addr = 32'h0;
        ask_kind = BurstKind$Index;
        vertex_in = 1'b0;
        byp_valid$d = 1'b0;
        header_check$h$0 = w$0$q;
        header_check$h$1 = w$1$q;
        header_check$h$2 = w$2$q;
        header_check$h$3 = w$3$q;
        header_check$h$4 = w$4$q;
        header_check$h$5 = w$5$q;
        header_check$h$6 = w$6$q;
        header_check$h$7 = w$7$q;
        header_check$h$8 = w$8$q;
        header_check$h$9 = w$9$q;
        header_check$h$10 = w$10$q;
        header_check$h$11 = w$11$q;
        header_check$h$12 = w$12$q;
        header_check$h$13 = w$13$q;
        header_check$h$14 = w$14$q;
        header_check$h$15 = w$15$q;
        header_check$h$16 = w$16$q;
        header_check$h$17 = w$17$q;
        header_check$h$18 = w$18$q;
        header_check$h$19 = w$19$q;
        header_check$h$20 = w$20$q;
        header_check$h$21 = w$21$q;
        header_check$h$22 = w$22$q;
        header_check$h$23 = w$23$q;
        header_check$base = base$q;
        header_check$max_width = max_width;
        header_check$max_height = max_height;
        index_check$r$0 = w$16$q;
        vertex_check$r$0 = w$16$q;
        index_check$r$1 = w$17$q;
        vertex_check$r$1 = w$17$q;
        index_check$r$2 = w$18$q;
        vertex_check$r$2 = w$18$q;
        index_check$r$3 = w$19$q;
        vertex_check$r$3 = w$19$q;
        index_check$r$4 = w$20$q;
        vertex_check$r$4 = w$20$q;
        index_check$r$5 = w$21$q;
        vertex_check$r$5 = w$21$q;
        index_check$r$6 = w$22$q;
        vertex_check$r$6 = w$22$q;
        index_check$r$7 = w$23$q;
        vertex_check$r$7 = w$23$q;
        is_ahead = st$q != ParserState$TriIndex;
        index_check$t = t$q;
        if (is_ahead) begin
            index_check$t = t$q + 32'h1;
        end
        index_check$triangles = triangles$q;
        index_check$vertices = vertices$q;
        v_cur = rec_v$0$q;
        if (k$q == 1) begin
            v_cur = rec_v$1$q;
        end
        if (k$q == 2) begin
            v_cur = rec_v$2$q;
        end
        slot = v_cur[(32'h0)+:(9)];
        group = slot >> four;
        lane = v_cur[(32'h0)+:(4)];
        held = 1'b0;
        if (group == 0) begin
            held = valid$0$q[lane];
        end
        if (group == 1) begin
            held = valid$1$q[lane];
        end
        if (group == 2) begin
            held = valid$2$q[lane];
        end
        if (group == 3) begin
            held = valid$3$q[lane];
        end
        if (group == 4) begin
            held = valid$4$q[lane];
        end
        if (group == 5) begin
            held = valid$5$q[lane];
        end
        if (group == 6) begin
            held = valid$6$q[lane];
        end
        if (group == 7) begin
            held = valid$7$q[lane];
        end
        if (group == 8) begin
            held = valid$8$q[lane];
        end
        if (group == 9) begin
            held = valid$9$q[lane];
        end
        if (group == 10) begin
            held = valid$10$q[lane];
        end
        if (group == 11) begin
            held = valid$11$q[lane];
        end
        if (group == 12) begin
            held = valid$12$q[lane];
        end
        if (group == 13) begin
            held = valid$13$q[lane];
        end
        if (group == 14) begin
            held = valid$14$q[lane];
        end
        if (group == 15) begin
            held = valid$15$q[lane];
        end
        if (group == 16) begin
            held = valid$16$q[lane];
        end
        if (group == 17) begin
            held = valid$17$q[lane];
        end
        if (group == 18) begin
            held = valid$18$q[lane];
        end
        if (group == 19) begin
            held = valid$19$q[lane];
        end
        if (group == 20) begin
            held = valid$20$q[lane];
        end
        if (group == 21) begin
            held = valid$21$q[lane];
        end
        if (group == 22) begin
            held = valid$22$q[lane];
        end
        if (group == 23) begin
            held = valid$23$q[lane];
        end
        if (group == 24) begin
            held = valid$24$q[lane];
        end
        if (group == 25) begin
            held = valid$25$q[lane];
        end
        if (group == 26) begin
            held = valid$26$q[lane];
        end
        if (group == 27) begin
            held = valid$27$q[lane];
        end
        if (group == 28) begin
            held = valid$28$q[lane];
        end
        if (group == 29) begin
            held = valid$29$q[lane];
        end
        if (group == 30) begin
            held = valid$30$q[lane];
        end
        if (group == 31) begin
            held = valid$31$q[lane];
        end
        tag = tag_ram$read_data;
        vtx = vtx_ram$read_data;
        if (byp_valid$q & (byp_tag$q[(32'h0)+:(9)] == slot)) begin
            tag = byp_tag$q;
            vtx = byp_vtx$q;
        end
        hit = held & (tag == v_cur);
        fetched = ((w$16$q[(32'h0)+:(16)]) & 74'h3ffffffffffffffffff) | (((w$17$q[(32'h0)+:(16)]) & 74'h3ffffffffffffffffff) << at_y) | (((w$18$q[(32'h0)+:(18)]) & 74'h3ffffffffffffffffff) << at_z) | (((w$19$q[(32'h0)+:(8)]) & 74'h3ffffffffffffffffff) << at_c0) | (((w$20$q[(32'h0)+:(8)]) & 74'h3ffffffffffffffffff) << at_c1) | (((w$21$q[(32'h0)+:(8)]) & 74'h3ffffffffffffffffff) << at_c2);
        tag_ram$write_enable = 1'b0;
        tag_ram$write_address = slot;
        tag_ram$write_data = v_cur;
        vtx_ram$write_enable = 1'b0;
        vtx_ram$write_address = slot;
        vtx_ram$write_data = fetched;
        frame_r$d = 1'b0;
        buffer_r$d = 1'b0;
        out_free = ~out_valid$q | out$ready;
        if (out_valid$q & out$ready) begin
            out_valid$d = 1'b0;
            frame_r$d = out_eof$q;
            buffer_r$d = out_eob$q;
        end
        complete$d = 1'b0;
        if (ar_valid$q & bus$ar_ready) begin
            ar_valid$d = 1'b0;
        end
        beat_in = burst$q & bus$r_valid & ~(ar_valid$q & ~bus$ar_ready);
        last_beat = 32'h1;
        if (kind$q == BurstKind$Header) begin
            last_beat = 32'h5;
        end
        if (beat_in) begin
            w$0$d = w$4$q;
            w$1$d = w$5$q;
            w$2$d = w$6$q;
            w$3$d = w$7$q;
            w$4$d = w$8$q;
            w$5$d = w$9$q;
            w$6$d = w$10$q;
            w$7$d = w$11$q;
            w$8$d = w$12$q;
            w$9$d = w$13$q;
            w$10$d = w$14$q;
            w$11$d = w$15$q;
            w$12$d = w$16$q;
            w$13$d = w$17$q;
            w$14$d = w$18$q;
            w$15$d = w$19$q;
            w$16$d = w$20$q;
            w$17$d = w$21$q;
            w$18$d = w$22$q;
            w$19$d = w$23$q;
            w$20$d = bus$r_data[(32'h0)+:(32)];
            w$21$d = bus$r_data[(32'h20)+:(32)];
            w$22$d = bus$r_data[(32'h40)+:(32)];
            w$23$d = bus$r_data[(32'h60)+:(32)];
            bus_error$d = bus_error$q | |bus$r_resp;
            beat$d = beat$q + 32'h1;
            if (beat$q == last_beat) begin
                burst$d = 1'b0;
                complete$d = 1'b1;
            end
        end
        go = 1'b0;
        check = 1'b0;
        look = 1'b0;
        hand = 1'b0;
        case (st$q)
            ParserState$Init:
                begin
                    go = start;
                end
            ParserState$Error:
                begin
                    go = start;
                end
            ParserState$Header:
                begin
                    check = complete$q;
                end
            ParserState$TriIndex:
                begin
                    check = complete$q;
                end
            ParserState$VertexFetch:
                begin
                    check = complete$q;
                    look = ~complete$q & ~(burst$q & (kind$q == BurstKind$Vertex));
                end
            ParserState$CpReady:
                begin
                    check = complete$q;
                    hand = out_free & ~complete$q;
                end
            ParserState$End:
                begin
                    if (out_free) begin
                        st$d = ParserState$Init;
                    end
                end
        endcase
        if (check & (kind$q == BurstKind$Index) & is_ahead) begin
            bus_error$d = 1'b0;
            ahead_valid$d = 1'b1;
            ahead_fault$d = index_check$fault;
            if (bus_error$q) begin
                ahead_fault$d = 32'ha;
            end
            ahead_v$0$d = w$16$q;
            ahead_iw$0$d = w$20$q[(32'h0)+:(16)];
            ahead_v$1$d = w$17$q;
            ahead_iw$1$d = w$21$q[(32'h0)+:(16)];
            ahead_v$2$d = w$18$q;
            ahead_iw$2$d = w$22$q[(32'h0)+:(16)];
            ahead_eob$d = w$19$q[32'h10];
            ahead_eof$d = w$19$q[32'h11];
        end
        else if (check) begin
            if (bus_error$q) begin
                bus_error$d = 1'b0;
                st$d = ParserState$Error;
                fault_r$d = 32'ha;
            end
            else begin
                case (kind$q)
                    BurstKind$Header:
                        begin
                            if (|header_check$fault) begin
                                st$d = ParserState$Error;
                                fault_r$d = header_check$fault;
                            end
                            else begin
                                render_r$d = 1'b1;
                                width_r$d = w$2$q[(32'h0)+:(16)];
                                height_r$d = w$2$q[(32'h10)+:(16)];
                                cull_r$d = w$1$q[32'h10];
                                background_r$d = w$9$q[(32'h0)+:(24)];
                                triangles$d = w$4$q;
                                vertices$d = w$5$q;
                                index_addr$d = base$q + w$6$q;
                                vertex_base$d = base$q + w$7$q;
                                if (|w$4$q) begin
                                    st$d = ParserState$TriIndex;
                                    ask = 1'b1;
                                    ask_addr = base$q + w$6$q;
                                end
                                else begin
                                    frame_r$d = 1'b1;
                                    buffer_r$d = 1'b1;
                                    st$d = ParserState$Init;
                                end
                            end
                        end
                    BurstKind$Index:
                        begin
                            if (|index_check$fault) begin
                                st$d = ParserState$Error;
                                fault_r$d = index_check$fault;
                            end
                            else begin
                                load_rec = 1'b1;
                                rec_v$0$d = w$16$q;
                                rec_iw$0$d = w$20$q[(32'h0)+:(16)];
                                rec_v$1$d = w$17$q;
                                rec_iw$1$d = w$21$q[(32'h0)+:(16)];
                                rec_v$2$d = w$18$q;
                                rec_iw$2$d = w$22$q[(32'h0)+:(16)];
                                rec_eob$d = w$19$q[32'h10];
                                rec_eof$d = w$19$q[32'h11];
                                kn = 32'h0;
                                st$d = ParserState$VertexFetch;
                                if (~w$19$q[32'h10]) begin
                                    ask = 1'b1;
                                    ask_addr = index_addr$q + 32'h20;
                                end
                            end
                        end
                    BurstKind$Vertex:
                        begin
                            if (|vertex_check$fault) begin
                                st$d = ParserState$Error;
                                fault_r$d = vertex_check$fault;
                            end
                            else begin
                                tag_ram$write_enable = 1'b1;
                                vtx_ram$write_enable = 1'b1;
                                if (group == 0) begin
                                    valid$0$d = (valid$0$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 1) begin
                                    valid$1$d = (valid$1$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 2) begin
                                    valid$2$d = (valid$2$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 3) begin
                                    valid$3$d = (valid$3$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 4) begin
                                    valid$4$d = (valid$4$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 5) begin
                                    valid$5$d = (valid$5$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 6) begin
                                    valid$6$d = (valid$6$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 7) begin
                                    valid$7$d = (valid$7$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 8) begin
                                    valid$8$d = (valid$8$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 9) begin
                                    valid$9$d = (valid$9$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 10) begin
                                    valid$10$d = (valid$10$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 11) begin
                                    valid$11$d = (valid$11$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 12) begin
                                    valid$12$d = (valid$12$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 13) begin
                                    valid$13$d = (valid$13$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 14) begin
                                    valid$14$d = (valid$14$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 15) begin
                                    valid$15$d = (valid$15$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 16) begin
                                    valid$16$d = (valid$16$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 17) begin
                                    valid$17$d = (valid$17$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 18) begin
                                    valid$18$d = (valid$18$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 19) begin
                                    valid$19$d = (valid$19$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 20) begin
                                    valid$20$d = (valid$20$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 21) begin
                                    valid$21$d = (valid$21$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 22) begin
                                    valid$22$d = (valid$22$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 23) begin
                                    valid$23$d = (valid$23$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 24) begin
                                    valid$24$d = (valid$24$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 25) begin
                                    valid$25$d = (valid$25$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 26) begin
                                    valid$26$d = (valid$26$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 27) begin
                                    valid$27$d = (valid$27$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 28) begin
                                    valid$28$d = (valid$28$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 29) begin
                                    valid$29$d = (valid$29$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 30) begin
                                    valid$30$d = (valid$30$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                if (group == 31) begin
                                    valid$31$d = (valid$31$q & ~(1 << (lane)) | ((1'b1) << (lane)));
                                end
                                byp_valid$d = 1'b1;
                                byp_tag$d = v_cur;
                                byp_vtx$d = fetched;
                                vertex_in = 1'b1;
                            end
                        end
                endcase
            end
        end
        cur = fetched;
        if (look) begin
            if (hit) begin
                cur = vtx;
                vertex_in = 1'b1;
            end
            else if (~burst$q) begin
                ask = 1'b1;
                ask_addr = vertex_base$q + (v_cur << five);
                ask_kind = BurstKind$Vertex;
            end
        end
        if (vertex_in) begin
            if (k$q == 0) begin
                asm$0$d = cur;
            end
            if (k$q == 1) begin
                asm$1$d = cur;
            end
            if (k$q == 2) begin
                asm$2$d = cur;
            end
            kn = k$q + 32'h1;
            if (k$q == 32'h2) begin
                if (out_free) begin
                    hand = 1'b1;
                end
                else begin
                    st$d = ParserState$CpReady;
                end
            end
        end
        if (hand) begin
            out_valid$d = 1'b1;
            out_vtx$0$d = asm$0$q;
            out_iw$0$d = rec_iw$0$q;
            out_vtx$1$d = asm$1$q;
            out_iw$1$d = rec_iw$1$q;
            out_vtx$2$d = asm$2$q;
            out_iw$2$d = rec_iw$2$q;
            if (vertex_in) begin
                out_vtx$2$d = cur;
            end
            out_eob$d = rec_eob$q;
            out_eof$d = rec_eof$q;
            if (rec_eob$q) begin
                st$d = ParserState$End;
            end
            else begin
                t$d = t$q + 32'h1;
                index_addr$d = index_addr$q + 32'h20;
                st$d = ParserState$TriIndex;
                if (ahead_valid$q) begin
                    ahead_valid$d = 1'b0;
                    if (|ahead_fault$q) begin
                        st$d = ParserState$Error;
                        fault_r$d = ahead_fault$q;
                    end
                    else begin
                        load_ahead = 1'b1;
                        rec_v$0$d = ahead_v$0$q;
                        rec_iw$0$d = ahead_iw$0$q;
                        rec_v$1$d = ahead_v$1$q;
                        rec_iw$1$d = ahead_iw$1$q;
                        rec_v$2$d = ahead_v$2$q;
                        rec_iw$2$d = ahead_iw$2$q;
                        rec_eob$d = ahead_eob$q;
                        rec_eof$d = ahead_eof$q;
                        kn = 32'h0;
                        st$d = ParserState$VertexFetch;
                        if (~ahead_eob$q) begin
                            ask = 1'b1;
                            ask_addr = index_addr$q + 32'h40;
                        end
                    end
                end
            end
        end
        if (go) begin
            fault_r$d = 32'h0;
            render_r$d = 1'b0;
            frame_r$d = 1'b0;
            buffer_r$d = 1'b0;
            bus_error$d = 1'b0;
            t$d = 32'h0;
            kn = 32'h0;
            ahead_valid$d = 1'b0;
            valid$0$d = 32'h0;
            valid$1$d = 32'h0;
            valid$2$d = 32'h0;
            valid$3$d = 32'h0;
            valid$4$d = 32'h0;
            valid$5$d = 32'h0;
            valid$6$d = 32'h0;
            valid$7$d = 32'h0;
            valid$8$d = 32'h0;
            valid$9$d = 32'h0;
            valid$10$d = 32'h0;
            valid$11$d = 32'h0;
            valid$12$d = 32'h0;
            valid$13$d = 32'h0;
            valid$14$d = 32'h0;
            valid$15$d = 32'h0;
            valid$16$d = 32'h0;
            valid$17$d = 32'h0;
            valid$18$d = 32'h0;
            valid$19$d = 32'h0;
            valid$20$d = 32'h0;
            valid$21$d = 32'h0;
            valid$22$d = 32'h0;
            valid$23$d = 32'h0;
            valid$24$d = 32'h0;
            valid$25$d = 32'h0;
            valid$26$d = 32'h0;
            valid$27$d = 32'h0;
            valid$28$d = 32'h0;
            valid$29$d = 32'h0;
            valid$30$d = 32'h0;
            valid$31$d = 32'h0;
            if (|address[(32'h0)+:(5)]) begin
                st$d = ParserState$Error;
                fault_r$d = 32'hb;
            end
            else begin
                base$d = address;
                st$d = ParserState$Header;
                ask = 1'b1;
                ask_addr = address;
                ask_kind = BurstKind$Header;
            end
        end
        if (ask) begin
            ar_valid$d = 1'b1;
            ar_addr$d = ask_addr;
            ar_len$d = 32'h1;
            if (ask_kind == BurstKind$Header) begin
                ar_len$d = 32'h5;
            end
            burst$d = 1'b1;
            kind$d = ask_kind;
            beat$d = 32'h0;
        end
        k$d = kn;
        rvn$0 = rec_v$0$q[(32'h0)+:(9)];
        rvn$1 = rec_v$1$q[(32'h0)+:(9)];
        rvn$2 = rec_v$2$q[(32'h0)+:(9)];
        if (load_rec) begin
            rvn$0 = w$16$q[(32'h0)+:(9)];
            rvn$1 = w$17$q[(32'h0)+:(9)];
            rvn$2 = w$18$q[(32'h0)+:(9)];
        end
        if (load_ahead) begin
            rvn$0 = ahead_v$0$q[(32'h0)+:(9)];
            rvn$1 = ahead_v$1$q[(32'h0)+:(9)];
            rvn$2 = ahead_v$2$q[(32'h0)+:(9)];
        end
        v_next = rvn$0;
        if (kn == 1) begin
            v_next = rvn$1;
        end
        if (kn == 2) begin
            v_next = rvn$2;
        end
        tag_ram$read_address = v_next;
        vtx_ram$read_address = v_next;
        bus$ar_valid = ar_valid$q;
        bus$ar_addr = ar_addr$q;
        bus$ar_len = ar_len$q;
        bus$ar_size = 32'h4;
        bus$ar_burst = 32'h1;
        bus$r_ready = 1'b1;
        out$valid = out_valid$q;
        out$v0_x = out_vtx$0$q[(32'h0)+:(16)];
        out$v0_y = out_vtx$0$q[(at_y)+:(16)];
        out$v0_z = out_vtx$0$q[(at_z)+:(18)];
        out$v0_c0 = out_vtx$0$q[(at_c0)+:(8)];
        out$v0_c1 = out_vtx$0$q[(at_c1)+:(8)];
        out$v0_c2 = out_vtx$0$q[(at_c2)+:(8)];
        out$v0_iw = out_iw$0$q;
        out$v1_x = out_vtx$1$q[(32'h0)+:(16)];
        out$v1_y = out_vtx$1$q[(at_y)+:(16)];
        out$v1_z = out_vtx$1$q[(at_z)+:(18)];
        out$v1_c0 = out_vtx$1$q[(at_c0)+:(8)];
        out$v1_c1 = out_vtx$1$q[(at_c1)+:(8)];
        out$v1_c2 = out_vtx$1$q[(at_c2)+:(8)];
        out$v1_iw = out_iw$1$q;
        out$v2_x = out_vtx$2$q[(32'h0)+:(16)];
        out$v2_y = out_vtx$2$q[(at_y)+:(16)];
        out$v2_z = out_vtx$2$q[(at_z)+:(18)];
        out$v2_c0 = out_vtx$2$q[(at_c0)+:(8)];
        out$v2_c1 = out_vtx$2$q[(at_c1)+:(8)];
        out$v2_c2 = out_vtx$2$q[(at_c2)+:(8)];
        out$v2_iw = out_iw$2$q;
        out$end_of_buffer = out_eob$q;
        out$end_of_frame = out_eof$q;
        render_valid = render_r$q;
        width = width_r$q;
        height = height_r$q;
        cull_back = cull_r$q;
        background = background_r$q;
        fault = fault_r$q;
        frame_done = frame_r$q;
        buffer_done = buffer_r$q;
        state = 32'h0;
        case (st$q)
            ParserState$Init:
                begin
                    state = 32'h0;
                end
            ParserState$Header:
                begin
                    state = 32'h1;
                end
            ParserState$TriIndex:
                begin
                    state = 32'h2;
                end
            ParserState$VertexFetch:
                begin
                    state = 32'h3;
                end
            ParserState$CpReady:
                begin
                    state = 32'h4;
                end
            ParserState$End:
                begin
                    state = 32'h5;
                end
            ParserState$Error:
                begin
                    state = 32'h6;
                end
        endcase
    end
    
endmodule // command_parser


module command_parser$ahead_eob(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_eob


module command_parser$ahead_eof(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_eof


module command_parser$ahead_fault(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_fault


module command_parser$ahead_iw$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_iw$0


module command_parser$ahead_iw$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_iw$1


module command_parser$ahead_iw$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_iw$2


module command_parser$ahead_v$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_v$0


module command_parser$ahead_v$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_v$1


module command_parser$ahead_v$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_v$2


module command_parser$ahead_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ahead_valid


module command_parser$ar_addr(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ar_addr


module command_parser$ar_len(d,q,clock);
    
    // Module arguments
    input wire  [7:0] d;
    output reg  [7:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 8'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ar_len


module command_parser$ar_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$ar_valid


module command_parser$asm$0(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$asm$0


module command_parser$asm$1(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$asm$1


module command_parser$asm$2(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$asm$2


module command_parser$background_r(d,q,clock);
    
    // Module arguments
    input wire  [23:0] d;
    output reg  [23:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 24'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$background_r


module command_parser$base(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$base


module command_parser$beat(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$beat


module command_parser$buffer_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$buffer_r


module command_parser$burst(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$burst


module command_parser$bus_error(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$bus_error


module command_parser$byp_tag(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$byp_tag


module command_parser$byp_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$byp_valid


module command_parser$byp_vtx(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$byp_vtx


module command_parser$complete(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$complete


module command_parser$cull_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$cull_r


module command_parser$fault_r(d,q,clock);
    
    // Module arguments
    input wire  [3:0] d;
    output reg  [3:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 4'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$fault_r


module command_parser$frame_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$frame_r


module command_parser$header_check(h$0,h$1,h$2,h$3,h$4,h$5,h$6,h$7,h$8,h$9,h$10,h$11,h$12,h$13,h$14,h$15,h$16,h$17,h$18,h$19,h$20,h$21,h$22,h$23,base,max_width,max_height,fault);
    
    // Module arguments
    input wire  [31:0] h$0;
    input wire  [31:0] h$1;
    input wire  [31:0] h$2;
    input wire  [31:0] h$3;
    input wire  [31:0] h$4;
    input wire  [31:0] h$5;
    input wire  [31:0] h$6;
    input wire  [31:0] h$7;
    input wire  [31:0] h$8;
    input wire  [31:0] h$9;
    input wire  [31:0] h$10;
    input wire  [31:0] h$11;
    input wire  [31:0] h$12;
    input wire  [31:0] h$13;
    input wire  [31:0] h$14;
    input wire  [31:0] h$15;
    input wire  [31:0] h$16;
    input wire  [31:0] h$17;
    input wire  [31:0] h$18;
    input wire  [31:0] h$19;
    input wire  [31:0] h$20;
    input wire  [31:0] h$21;
    input wire  [31:0] h$22;
    input wire  [31:0] h$23;
    input wire  [31:0] base;
    input wire  [15:0] max_width;
    input wire  [15:0] max_height;
    output reg  [3:0] fault;
    
    // Constant declarations
    localparam  version = 16'h1;
    localparam  side = 16'h400;
    localparam  header_bytes = 38'h60;
    localparam  five = 8'h5;
    localparam  two_32 = 33'h100000000;
    
    // Stub signals
    reg  [31:0] magic$w;
    wire  magic$eq;
    reg  [31:0] size_class$w;
    wire  size_class$eq;
    reg  [31:0] formats$0$w;
    wire  formats$0$eq;
    reg  [31:0] formats$1$w;
    wire  formats$1$eq;
    reg  [31:0] formats$2$w;
    wire  formats$2$eq;
    reg  [31:0] formats$3$w;
    wire  formats$3$eq;
    reg  [31:0] formats$4$w;
    wire  formats$4$eq;
    reg  [31:0] formats$5$w;
    wire  formats$5$eq;
    reg  [31:0] formats$6$w;
    wire  formats$6$eq;
    reg  [31:0] formats$7$w;
    wire  formats$7$eq;
    reg  [31:0] formats$8$w;
    wire  formats$8$eq;
    reg  [31:0] formats$9$w;
    wire  formats$9$eq;
    reg  [31:0] formats$10$w;
    wire  formats$10$eq;
    
    // Local signals
    reg  [15:0] width;
    reg  [15:0] height;
    reg  build_bad;
    reg  [37:0] index_at;
    reg  [37:0] index_end;
    reg  [37:0] vertex_at;
    reg  [37:0] vertex_end;
    reg  [37:0] length;
    reg  layout_bad;
    
    // Sub module instances
    command_parser$header_check$magic magic(
        .w(magic$w),
        .eq(magic$eq)
    );
    command_parser$header_check$size_class size_class(
        .w(size_class$w),
        .eq(size_class$eq)
    );
    command_parser$header_check$formats$0 formats$0(
        .w(formats$0$w),
        .eq(formats$0$eq)
    );
    command_parser$header_check$formats$1 formats$1(
        .w(formats$1$w),
        .eq(formats$1$eq)
    );
    command_parser$header_check$formats$2 formats$2(
        .w(formats$2$w),
        .eq(formats$2$eq)
    );
    command_parser$header_check$formats$3 formats$3(
        .w(formats$3$w),
        .eq(formats$3$eq)
    );
    command_parser$header_check$formats$4 formats$4(
        .w(formats$4$w),
        .eq(formats$4$eq)
    );
    command_parser$header_check$formats$5 formats$5(
        .w(formats$5$w),
        .eq(formats$5$eq)
    );
    command_parser$header_check$formats$6 formats$6(
        .w(formats$6$w),
        .eq(formats$6$eq)
    );
    command_parser$header_check$formats$7 formats$7(
        .w(formats$7$w),
        .eq(formats$7$eq)
    );
    command_parser$header_check$formats$8 formats$8(
        .w(formats$8$w),
        .eq(formats$8$eq)
    );
    command_parser$header_check$formats$9 formats$9(
        .w(formats$9$w),
        .eq(formats$9$eq)
    );
    command_parser$header_check$formats$10 formats$10(
        .w(formats$10$w),
        .eq(formats$10$eq)
    );
    
    // Update code
    always @(*) begin
        magic$w = h$0;
        size_class$w = h$3;
        formats$0$w = h$10;
        formats$1$w = h$11;
        formats$2$w = h$12;
        formats$3$w = h$13;
        formats$4$w = h$14;
        formats$5$w = h$15;
        formats$6$w = h$16;
        formats$7$w = h$17;
        formats$8$w = h$18;
        formats$9$w = h$19;
        formats$10$w = h$20;
        width = h$2[(32'h0)+:(16)];
        height = h$2[(32'h10)+:(16)];
        build_bad = ~(size_class$eq & formats$0$eq & formats$1$eq & formats$2$eq & formats$3$eq & formats$4$eq & formats$5$eq & formats$6$eq & formats$7$eq & formats$8$eq & formats$9$eq & formats$10$eq) | ~|width | ~|height | (width > side) | (height > side);
        index_at = ((h$6) & 38'h3fffffffff);
        vertex_at = ((h$7) & 38'h3fffffffff);
        length = ((h$8) & 38'h3fffffffff);
        index_end = index_at + (((h$4) & 38'h3fffffffff) << five);
        vertex_end = vertex_at + (((h$5) & 38'h3fffffffff) << five);
        layout_bad = |h$6[(32'h0)+:(5)] | (index_at < header_bytes) | (index_end > length) | |h$7[(32'h0)+:(5)] | (vertex_at < header_bytes) | (vertex_end > length) | (|h$4 & |h$5 & (index_at < vertex_end) & (vertex_at < index_end)) | ((((base) & 33'h1ffffffff) + ((h$8) & 33'h1ffffffff)) > two_32);
        fault = 32'h0;
        if ((width > max_width) | (height > max_height)) begin
            fault = 32'hc;
        end
        if (layout_bad) begin
            fault = 32'h5;
        end
        if (build_bad) begin
            fault = 32'h4;
        end
        if (|h$1[(32'h11)+:(15)] | |h$9[(32'h18)+:(8)] | |h$21 | |h$22 | |h$23) begin
            fault = 32'h3;
        end
        if (h$1[(32'h0)+:(16)] != version) begin
            fault = 32'h2;
        end
        if (~magic$eq) begin
            fault = 32'h1;
        end
    end
    
endmodule // command_parser$header_check


module command_parser$header_check$formats$0(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h3040b;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$0


module command_parser$header_check$formats$1(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h31001;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$1


module command_parser$header_check$formats$10(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h11a01;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$10


module command_parser$header_check$formats$2(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h60008;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$2


module command_parser$header_check$formats$3(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h20f01;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$3


module command_parser$header_check$formats$4(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h1801;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$4


module command_parser$header_check$formats$5(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h12315;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$5


module command_parser$header_check$formats$6(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h12205;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$6


module command_parser$header_check$formats$7(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h12201;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$7


module command_parser$header_check$formats$8(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h1160d;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$8


module command_parser$header_check$formats$9(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h11609;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$formats$9


module command_parser$header_check$magic(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'h42565045;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$magic


module command_parser$header_check$size_class(w,eq);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  eq;
    
    // Constant declarations
    localparam  word = 32'ha;
    
    // Update code
    always @(*) begin
        eq = w == word;
    end
    
endmodule // command_parser$header_check$size_class


module command_parser$height_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$height_r


module command_parser$index_addr(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$index_addr


module command_parser$index_check(r$0,r$1,r$2,r$3,r$4,r$5,r$6,r$7,t,triangles,vertices,fault);
    
    // Module arguments
    input wire  [31:0] r$0;
    input wire  [31:0] r$1;
    input wire  [31:0] r$2;
    input wire  [31:0] r$3;
    input wire  [31:0] r$4;
    input wire  [31:0] r$5;
    input wire  [31:0] r$6;
    input wire  [31:0] r$7;
    input wire  [31:0] t;
    input wire  [31:0] triangles;
    input wire  [31:0] vertices;
    output reg  [3:0] fault;
    
    // Constant declarations
    localparam  no_texture = 16'hffff;
    localparam  one = 32'h8000;
    
    // Stub signals
    reg  [31:0] iw$0$w;
    wire  iw$0$ok;
    reg  [31:0] iw$1$w;
    wire  iw$1$ok;
    reg  [31:0] iw$2$w;
    wire  iw$2$ok;
    
    // Local signals
    reg  last;
    reg  eob;
    reg  eof;
    reg  ti_bad;
    reg  iw_bad;
    
    // Sub module instances
    command_parser$index_check$iw$0 iw$0(
        .w(iw$0$w),
        .ok(iw$0$ok)
    );
    command_parser$index_check$iw$1 iw$1(
        .w(iw$1$w),
        .ok(iw$1$ok)
    );
    command_parser$index_check$iw$2 iw$2(
        .w(iw$2$w),
        .ok(iw$2$ok)
    );
    
    // Update code
    always @(*) begin
        last = (t + 32'h1) == triangles;
        eob = r$3[32'h10];
        eof = r$3[32'h11];
        ti_bad = (r$3[(32'h0)+:(16)] != no_texture) | |r$3[(32'h12)+:(14)] | (eob ^ last) | (eof & ~last);
        iw$0$w = r$4;
        iw$1$w = r$5;
        iw$2$w = r$6;
        iw_bad = ~iw$0$ok | ~iw$1$ok | ~iw$2$ok | (r$4 > one) | (r$5 > one) | (r$6 > one) | ~((r$4 == one) | (r$5 == one) | (r$6 == one));
        fault = 32'h0;
        if (|r$7) begin
            fault = 32'h3;
        end
        if (iw_bad) begin
            fault = 32'h8;
        end
        if (ti_bad) begin
            fault = 32'h7;
        end
        if ((r$0 >= vertices) | (r$1 >= vertices) | (r$2 >= vertices)) begin
            fault = 32'h6;
        end
    end
    
endmodule // command_parser$index_check


module command_parser$index_check$iw$0(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'h10;
    localparam  ones = 32'hffff;
    localparam  sign_ext = 1'b0;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$index_check$iw$0


module command_parser$index_check$iw$1(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'h10;
    localparam  ones = 32'hffff;
    localparam  sign_ext = 1'b0;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$index_check$iw$1


module command_parser$index_check$iw$2(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'h10;
    localparam  ones = 32'hffff;
    localparam  sign_ext = 1'b0;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$index_check$iw$2


module command_parser$k(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 2'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$k


module command_parser$kind(d,q,clock);
    
    // Module arguments
    input wire  [1:0] d;
    output reg  [1:0] q;
    input wire  clock;
    
    // Enums
    localparam BurstKind$Header = 0;
    localparam BurstKind$Index = 1;
    localparam BurstKind$Vertex = 2;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$kind


module command_parser$out_eob(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_eob


module command_parser$out_eof(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_eof


module command_parser$out_iw$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_iw$0


module command_parser$out_iw$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_iw$1


module command_parser$out_iw$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_iw$2


module command_parser$out_valid(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_valid


module command_parser$out_vtx$0(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_vtx$0


module command_parser$out_vtx$1(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_vtx$1


module command_parser$out_vtx$2(d,q,clock);
    
    // Module arguments
    input wire  [73:0] d;
    output reg  [73:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 74'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$out_vtx$2


module command_parser$rec_eob(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$rec_eob


module command_parser$rec_eof(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$rec_eof


module command_parser$rec_iw$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$rec_iw$0


module command_parser$rec_iw$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$rec_iw$1


module command_parser$rec_iw$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$rec_iw$2


module command_parser$rec_v$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$rec_v$0


module command_parser$rec_v$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$rec_v$1


module command_parser$rec_v$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$rec_v$2


module command_parser$render_r(d,q,clock);
    
    // Module arguments
    input wire  d;
    output reg  q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 1'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$render_r


module command_parser$st(d,q,clock);
    
    // Module arguments
    input wire  [2:0] d;
    output reg  [2:0] q;
    input wire  clock;
    
    // Enums
    localparam ParserState$Init = 0;
    localparam ParserState$Header = 1;
    localparam ParserState$TriIndex = 2;
    localparam ParserState$VertexFetch = 3;
    localparam ParserState$CpReady = 4;
    localparam ParserState$End = 5;
    localparam ParserState$Error = 6;
    
    // Update code (custom)
    initial begin
       q = 64'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$st


module command_parser$t(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$t


module command_parser$tag_ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [8:0] read_address;
    input wire  read_clock;
    output reg  [31:0] read_data;
    input wire  [8:0] write_address;
    input wire  write_clock;
    input wire  [31:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[31:0] mem[511:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // command_parser$tag_ram


module command_parser$triangles(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$triangles


module command_parser$valid$0(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$0


module command_parser$valid$1(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$1


module command_parser$valid$10(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$10


module command_parser$valid$11(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$11


module command_parser$valid$12(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$12


module command_parser$valid$13(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$13


module command_parser$valid$14(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$14


module command_parser$valid$15(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$15


module command_parser$valid$16(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$16


module command_parser$valid$17(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$17


module command_parser$valid$18(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$18


module command_parser$valid$19(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$19


module command_parser$valid$2(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$2


module command_parser$valid$20(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$20


module command_parser$valid$21(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$21


module command_parser$valid$22(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$22


module command_parser$valid$23(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$23


module command_parser$valid$24(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$24


module command_parser$valid$25(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$25


module command_parser$valid$26(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$26


module command_parser$valid$27(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$27


module command_parser$valid$28(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$28


module command_parser$valid$29(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$29


module command_parser$valid$3(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$3


module command_parser$valid$30(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$30


module command_parser$valid$31(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$31


module command_parser$valid$4(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$4


module command_parser$valid$5(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$5


module command_parser$valid$6(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$6


module command_parser$valid$7(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$7


module command_parser$valid$8(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$8


module command_parser$valid$9(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$valid$9


module command_parser$vertex_base(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$vertex_base


module command_parser$vertex_check(r$0,r$1,r$2,r$3,r$4,r$5,r$6,r$7,fault);
    
    // Module arguments
    input wire  [31:0] r$0;
    input wire  [31:0] r$1;
    input wire  [31:0] r$2;
    input wire  [31:0] r$3;
    input wire  [31:0] r$4;
    input wire  [31:0] r$5;
    input wire  [31:0] r$6;
    input wire  [31:0] r$7;
    output reg  [3:0] fault;
    
    // Stub signals
    reg  [31:0] fits$0$w;
    wire  fits$0$ok;
    reg  [31:0] fits$1$w;
    wire  fits$1$ok;
    reg  [31:0] fits$2$w;
    wire  fits$2$ok;
    reg  [31:0] fits$3$w;
    wire  fits$3$ok;
    reg  [31:0] fits$4$w;
    wire  fits$4$ok;
    reg  [31:0] fits$5$w;
    wire  fits$5$ok;
    
    // Sub module instances
    command_parser$vertex_check$fits$0 fits$0(
        .w(fits$0$w),
        .ok(fits$0$ok)
    );
    command_parser$vertex_check$fits$1 fits$1(
        .w(fits$1$w),
        .ok(fits$1$ok)
    );
    command_parser$vertex_check$fits$2 fits$2(
        .w(fits$2$w),
        .ok(fits$2$ok)
    );
    command_parser$vertex_check$fits$3 fits$3(
        .w(fits$3$w),
        .ok(fits$3$ok)
    );
    command_parser$vertex_check$fits$4 fits$4(
        .w(fits$4$w),
        .ok(fits$4$ok)
    );
    command_parser$vertex_check$fits$5 fits$5(
        .w(fits$5$w),
        .ok(fits$5$ok)
    );
    
    // Update code
    always @(*) begin
        fits$0$w = r$0;
        fits$1$w = r$1;
        fits$2$w = r$2;
        fits$3$w = r$3;
        fits$4$w = r$4;
        fits$5$w = r$5;
        fault = 32'h0;
        if (|r$6 | |r$7) begin
            fault = 32'h3;
        end
        if (~(fits$0$ok & fits$1$ok & fits$2$ok & fits$3$ok & fits$4$ok & fits$5$ok)) begin
            fault = 32'h9;
        end
    end
    
endmodule // command_parser$vertex_check


module command_parser$vertex_check$fits$0(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'hf;
    localparam  ones = 32'h1ffff;
    localparam  sign_ext = 1'b1;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$vertex_check$fits$0


module command_parser$vertex_check$fits$1(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'hf;
    localparam  ones = 32'h1ffff;
    localparam  sign_ext = 1'b1;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$vertex_check$fits$1


module command_parser$vertex_check$fits$2(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'h11;
    localparam  ones = 32'h7fff;
    localparam  sign_ext = 1'b1;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$vertex_check$fits$2


module command_parser$vertex_check$fits$3(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'h8;
    localparam  ones = 32'hffffff;
    localparam  sign_ext = 1'b0;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$vertex_check$fits$3


module command_parser$vertex_check$fits$4(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'h8;
    localparam  ones = 32'hffffff;
    localparam  sign_ext = 1'b0;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$vertex_check$fits$4


module command_parser$vertex_check$fits$5(w,ok);
    
    // Module arguments
    input wire  [31:0] w;
    output reg  ok;
    
    // Constant declarations
    localparam  shift = 8'h8;
    localparam  ones = 32'hffffff;
    localparam  sign_ext = 1'b0;
    localparam  every = 1'b0;
    
    // Local signals
    reg  [31:0] high;
    
    // Update code
    always @(*) begin
        high = w >> shift;
        ok = every | ~|high | (sign_ext & (high == ones));
    end
    
endmodule // command_parser$vertex_check$fits$5


module command_parser$vertices(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$vertices


module command_parser$vtx_ram(read_address,read_clock,read_data,write_address,write_clock,write_data,write_enable);
    
    // Module arguments
    input wire  [8:0] read_address;
    input wire  read_clock;
    output reg  [73:0] read_data;
    input wire  [8:0] write_address;
    input wire  write_clock;
    input wire  [73:0] write_data;
    input wire  write_enable;
    
    // Update code (custom)
    reg[73:0] mem[511:0];
    
    
    
    always @(posedge read_clock) begin
       read_data <= mem[read_address];
    end
    
    always @(posedge write_clock) begin
       if (write_enable) begin
          mem[write_address] <= write_data;
       end
    end
                
endmodule // command_parser$vtx_ram


module command_parser$w$0(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$0


module command_parser$w$1(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$1


module command_parser$w$10(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$10


module command_parser$w$11(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$11


module command_parser$w$12(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$12


module command_parser$w$13(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$13


module command_parser$w$14(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$14


module command_parser$w$15(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$15


module command_parser$w$16(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$16


module command_parser$w$17(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$17


module command_parser$w$18(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$18


module command_parser$w$19(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$19


module command_parser$w$2(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$2


module command_parser$w$20(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$20


module command_parser$w$21(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$21


module command_parser$w$22(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$22


module command_parser$w$23(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$23


module command_parser$w$3(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$3


module command_parser$w$4(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$4


module command_parser$w$5(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$5


module command_parser$w$6(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$6


module command_parser$w$7(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$7


module command_parser$w$8(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$8


module command_parser$w$9(d,q,clock);
    
    // Module arguments
    input wire  [31:0] d;
    output reg  [31:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 32'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$w$9


module command_parser$width_r(d,q,clock);
    
    // Module arguments
    input wire  [15:0] d;
    output reg  [15:0] q;
    input wire  clock;
    
    // Update code (custom)
    initial begin
       q = 16'h0;
    end
    
    always @(posedge clock) begin
       q <= d;
    end
          
endmodule // command_parser$width_r
